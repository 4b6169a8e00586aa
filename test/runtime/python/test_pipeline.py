"""The Python module: what a program gets back equals what `facet run` writes, errors are Python
exceptions that name the problem, and two pipelines run in parallel from two threads."""

import json
import os
import subprocess
import sys
import threading

import cv2
import numpy as np
import pytest

import facet

STEMS = ["learn0", "learn18", "learn20", "learn27", "learn36", "learn5"]
INTRINSICS = (525.0, 525.0, 319.5, 239.5)  # data/mosd/intrinsics.yaml


def depth_of(mosd, stem):
    depth = cv2.imread(str(mosd / "depth" / f"{stem}.png"), cv2.IMREAD_UNCHANGED)
    assert depth is not None and depth.dtype == np.uint16
    return depth


@pytest.fixture(scope="module")
def cli_output(tabletop, tmp_path_factory):
    out = tmp_path_factory.mktemp("cli")
    subprocess.run([os.environ["FACET_CLI"], "run", str(tabletop), "--param", f"output={out}"],
                   check=True, capture_output=True)
    return out


def test_labels_and_objects_equal_the_cli_files_on_every_bundled_frame(tabletop, mosd,
                                                                        cli_output):
    seg = facet.Pipeline(tabletop)
    for stem in STEMS:
        out = seg(depth_of(mosd, stem), intrinsics=INTRINSICS, stem=stem)
        labels = out["labels"]
        assert labels.dtype == np.int32 and labels.shape == (480, 640)
        written = cv2.imread(str(cli_output / "labels" / f"{stem}.png"), cv2.IMREAD_UNCHANGED)
        assert written is not None
        assert np.array_equal(labels.astype(np.uint16), written), stem
        assert labels.max() >= 1
        with open(cli_output / "objects" / f"{stem}.json") as file:
            written_objects = json.load(file)["objects"]
        assert out["objects"] == written_objects, stem
        # The same types too: json.dumps spells 1 and 1.0 differently.
        assert json.dumps(out["objects"]) == json.dumps(written_objects), stem
        assert out["planes"]["table_id"] >= 1
        assert set(out.timings) >= {"median", "normals", "objects", "shapes"}
        assert all(ms >= 0.0 for ms in out.timings.values())


def test_outputs_are_read_only_views_that_outlive_the_pipeline(tabletop, mosd):
    seg = facet.Pipeline(tabletop)
    labels = seg(depth_of(mosd, "learn0"), intrinsics=INTRINSICS)["labels"]
    del seg
    assert not labels.flags.writeable
    assert labels.max() >= 1  # the packet behind the view is still alive
    with pytest.raises(ValueError):
        labels[0, 0] = 1


def test_intrinsics_as_dict_matrix_and_tuple_agree_and_metres_work_too(tabletop, mosd):
    seg = facet.Pipeline(tabletop)
    depth = depth_of(mosd, "learn18")
    fx, fy, cx, cy = INTRINSICS
    reference = seg(depth, intrinsics=INTRINSICS)["labels"]
    as_dict = seg(depth, intrinsics={"fx": fx, "fy": fy, "cx": cx, "cy": cy})["labels"]
    matrix = np.array([[fx, 0, cx], [0, fy, cy], [0, 0, 1]])
    as_matrix = seg(depth, intrinsics=matrix)["labels"]
    metres = seg(depth.astype(np.float32) / 1000.0, intrinsics=INTRINSICS)["labels"]
    assert np.array_equal(reference, as_dict)
    assert np.array_equal(reference, as_matrix)
    # float32 metres from a division differ from the millimetres in the last bit here and there:
    # the same objects, nearly every pixel the same.
    assert metres.max() == reference.max()
    assert np.mean(metres == reference) > 0.99


def test_a_non_contiguous_slice_is_copied_with_a_warning(tabletop, mosd):
    seg = facet.Pipeline(tabletop)
    depth = depth_of(mosd, "learn5")
    wide = np.zeros((480, 1280), np.uint16)
    wide[:, ::2] = depth
    with pytest.warns(RuntimeWarning, match="not C-contiguous"):
        sliced = seg(wide[:, ::2], intrinsics=INTRINSICS)["labels"]
    assert np.array_equal(sliced, seg(depth, intrinsics=INTRINSICS)["labels"])


@pytest.mark.parametrize("depth, intrinsics, error, match", [
    (np.zeros((480, 640, 3), np.uint16), INTRINSICS, ValueError, r"2-D array"),
    (np.zeros((480, 640), np.int64), INTRINSICS, TypeError, r"uint16 \(millimetres\) or float32"),
    (np.zeros((0, 640), np.uint16), INTRINSICS, ValueError, r"empty"),
    ([[1, 2], [3, 4]], INTRINSICS, TypeError, r"numpy array"),
    (np.zeros((480, 640), np.uint16), (525.0, 525.0, 319.5), ValueError, r"got 3 numbers"),
    (np.zeros((480, 640), np.uint16), None, ValueError, r"missing intrinsics"),
    (np.zeros((480, 640), np.uint16), {"fx": 525.0}, ValueError, r"no 'fy'"),
    (np.zeros((480, 640), np.uint16), np.eye(4), ValueError, r"3x3"),
    (np.zeros((480, 640), np.uint16), (float("nan"), 525, 319.5, 239.5), ValueError, r"finite"),
    (np.zeros((480, 640), np.uint16), (0, 525, 319.5, 239.5), ValueError, r"positive"),
])
def test_bad_input_is_a_python_exception_naming_the_problem(tabletop, depth, intrinsics, error,
                                                            match):
    seg = facet.Pipeline(tabletop)
    with pytest.raises(error, match=match):
        seg(depth, intrinsics=intrinsics)


def test_an_empty_frame_gives_no_objects_not_a_crash(tabletop):
    seg = facet.Pipeline(tabletop)
    out = seg(np.zeros((480, 640), np.uint16), intrinsics=INTRINSICS)
    labels = out["labels"]
    assert labels is None or labels.max() == 0


def test_graph_errors_carry_every_diagnostic_with_its_line(tabletop, tmp_path):
    with pytest.raises(facet.GraphError) as caught:
        facet.Pipeline(tabletop, set={"normals.radios": 2, "edges.threshold": 7})
    text = str(caught.value)
    assert "radios" in text and "did you mean 'radius'" in text
    assert "threshold" in text
    diagnostics = caught.value.diagnostics
    assert [d["severity"] for d in diagnostics].count("error") == 2
    assert all(d["file"] == "<command line>" for d in diagnostics if d["severity"] == "error")

    broken = tmp_path / "broken.yaml"
    broken.write_text("facet: 1\nnodes:\n  a: {stage: filter.mediam}\noutputs: {x: a.depth}\n")
    with pytest.raises(facet.GraphError) as caught:
        facet.Pipeline(broken)
    first = caught.value.diagnostics[0]
    assert (first["file"], first["line"], first["column"]) == (str(broken), 3, 14)
    assert "unknown stage 'filter.mediam'" in first["message"]
    with pytest.raises(facet.GraphError, match="cannot read graph file"):
        facet.Pipeline(tmp_path / "missing.yaml")


def test_a_graph_without_inputs_reads_its_own_source(source_dir, mosd, tmp_path):
    graph = tmp_path / "pulled.yaml"
    graph.write_text(
        "facet: 1\n"
        "nodes:\n"
        f"  source: {{stage: io.frames, params: {{path: \"{mosd}\", labels_dir: \"\"}}}}\n"
        "  points: {stage: convert.points, in: {depth: source.depth}}\n"
        "outputs: {points: points.points, depth: source.depth}\n")
    seg = facet.Pipeline(graph)
    assert seg.inputs == []
    with pytest.raises(ValueError, match="declares no inputs"):
        seg(np.zeros((480, 640), np.uint16), intrinsics=INTRINSICS)
    frames = []
    while (out := seg()) is not None:
        frames.append(out)
        assert out["points"].shape == (480, 640, 3) and out["points"].dtype == np.float32
        assert out["depth"].dtype == np.uint16
    assert len(frames) == len(STEMS)


def test_two_pipelines_run_in_parallel_from_two_threads(tabletop, mosd):
    depths = [depth_of(mosd, stem) for stem in STEMS]
    seg = facet.Pipeline(tabletop)
    reference = [seg(d, intrinsics=INTRINSICS)["labels"].copy() for d in depths]
    results = [None, None]

    def work(slot):
        own = facet.Pipeline(tabletop)
        results[slot] = [own(d, intrinsics=INTRINSICS)["labels"].copy() for d in depths]

    threads = [threading.Thread(target=work, args=(slot,)) for slot in range(2)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    for result in results:
        assert result is not None
        assert all(np.array_equal(a, b) for a, b in zip(result, reference))


def test_stages_and_inspect_show_what_the_cli_lists():
    names = [stage["name"] for stage in facet.stages()]
    assert "normals.cross" in names and "partition.graph" in names
    assert all(stage["summary"] for stage in facet.stages())
    text = facet.inspect("normals.cross")
    assert "radius" in text
    with pytest.raises(ValueError, match="did you mean 'normals.cross'"):
        facet.inspect("normals.cros")


def test_the_example_segments_a_bundled_frame(source_dir, tmp_path):
    pytest.importorskip("matplotlib")
    picture = tmp_path / "overlay.png"
    done = subprocess.run(
        [sys.executable, str(source_dir / "examples" / "segment.py"), "--save", str(picture)],
        capture_output=True, text=True, env={**os.environ, "MPLBACKEND": "Agg"})
    assert done.returncode == 0, done.stderr
    assert "objects" in done.stdout
    assert picture.stat().st_size > 10000
