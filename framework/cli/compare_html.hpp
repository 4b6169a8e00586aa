#pragma once
// report.html of `facet compare`: one self-contained page (inline CSS and SVG, images as data
// URIs, no external resource) with the variants' figures, plots and images side by side.

#include <ostream>
#include <vector>

#include "compare_sweep.hpp"
#include "facet/framework/compare_summary.hpp"
#include "report_context.hpp"
#include "report_images.hpp"

namespace facet::cli {

// `plots`: a sweep's SVG plots (compare_sweep.hpp), embedded as they are; empty otherwise.
void write_compare_html(std::ostream& out, const CompareSummary& summary,
                        const std::vector<ImageRow>& images, const ReportContext& context,
                        const std::vector<SweepPlotFile>& plots = {});

}  // namespace facet::cli
