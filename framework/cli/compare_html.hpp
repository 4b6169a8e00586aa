#pragma once
// report.html of `facet compare`: one self-contained page (inline CSS and SVG, images as data
// URIs, no external resource) with the variants' figures, plots and images side by side.

#include <ostream>
#include <vector>

#include "facet/framework/compare_summary.hpp"
#include "report_images.hpp"

namespace facet::cli {

void write_compare_html(std::ostream& out, const CompareSummary& summary,
                        const std::vector<ImageRow>& images);

}  // namespace facet::cli
