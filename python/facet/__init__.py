"""facet: model-free 3D scene segmentation from depth images.

    import facet, cv2
    seg = facet.Pipeline("graphs/tabletop.yaml")
    depth = cv2.imread("data/mosd/depth/learn0.png", cv2.IMREAD_UNCHANGED)  # uint16 mm
    out = seg(depth, intrinsics=(525.0, 525.0, 319.5, 239.5))
    out["labels"]    # H x W int32, 0 = background, 1..N objects
    out["objects"]   # list of dicts, the fields of docs/objects-json.md
    out.timings      # milliseconds per node

See docs/embedding.md.
"""

from . import _facet
from ._facet import GraphError, ProcessError

__all__ = ["Pipeline", "Result", "GraphError", "ProcessError", "stages", "inspect"]


class Result(dict):
    """The graph outputs of one frame by name, with the frame's timings and warnings."""

    def __init__(self, outputs, timings, warnings, frame_index):
        super().__init__(outputs)
        self.timings = timings            # node id -> milliseconds, the nodes that ran
        self.warnings = warnings          # "node 'N', frame F: ..." as the command line prints
        self.frame_index = frame_index    # 0 for the first frame of this pipeline


class Pipeline:
    """A graph file, run one frame per call.

    Pipeline(graph, params={"name": value}, set={"node.param": value}, variant="",
             plugin_path=[dirs], run_sinks=False)

    The graph's `inputs:` are fed by the caller and its `outputs:` returned; only the nodes the
    outputs need run (run_sinks=True runs the file sinks too). Errors in the graph raise
    GraphError, whose `diagnostics` list every problem with its file, line and column.
    """

    def __init__(self, graph, *, params=None, set=None, variant="", plugin_path=None,
                 run_sinks=False):
        paths = [plugin_path] if isinstance(plugin_path, (str, bytes)) else (plugin_path or [])
        self._pipeline = _facet._Pipeline(str(graph), dict(params or {}), dict(set or {}),
                                          variant, [str(p) for p in paths], bool(run_sinks))

    def __call__(self, depth=None, *, intrinsics=None, stem="", inputs=None):
        """Segments one depth image (H x W, uint16 millimetres or float32 metres).

        intrinsics: (fx, fy, cx, cy), a dict with those keys, or a 3 x 3 camera matrix.
        stem: the frame's name, used by file sinks (default frame_<index>).
        inputs: {name: array} for graphs with several inputs.
        A graph without inputs reads its own source: call it with no depth; it returns None
        when the source has no more frames.
        """
        result = self._pipeline.call(depth, intrinsics, stem, dict(inputs or {}))
        return None if result is None else Result(*result)

    @property
    def name(self):
        return self._pipeline.name

    @property
    def inputs(self):
        """[(name, packet type)] of the graph's inputs."""
        return self._pipeline.inputs

    @property
    def outputs(self):
        """[(name, packet type)] of the graph's outputs."""
        return self._pipeline.outputs

    @property
    def nodes(self):
        """The nodes that run, in execution order."""
        return self._pipeline.nodes

    def close(self):
        """Closes the stages (sinks flush their files); raises ProcessError if one fails."""
        self._pipeline.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False


def stages(plugin_path=None):
    """Every stage the plugins provide: [{"name", "plugin", "summary"}], as `facet list`."""
    return _facet.stages([str(p) for p in (plugin_path or [])])


def inspect(name, plugin_path=None):
    """The documentation of a stage, as `facet inspect NAME` prints it."""
    return _facet.inspect(name, [str(p) for p in (plugin_path or [])])
