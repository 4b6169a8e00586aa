// The comparison report as a browser shows it: the report docs/compare.md shows, made by the
// command quoted above its screenshot, is loaded in headless Chromium, which must decode every
// image and lay out the tables; its screenshot is checked (size, not blank, the report's colours)
// and is what docs/images/ holds: with FACET_SCREENSHOT_DIR set, the test copies it there
// (scripts/update_compare_screenshot.sh).

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "cli_runner.hpp"
#include "headless_chromium.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

// The size of the window the screenshot is taken in, as docs/compare.md says.
constexpr int kScreenshotWidthPx = 1400;
constexpr int kScreenshotHeightPx = 1250;

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t count = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
    ++count;
  return count;
}

// Where docs/compare.md's screenshot comes from: the arguments of the command in the comment
// `<!-- screenshot of: facet compare ARGS -->` and the image file the next picture shows.
struct DocScreenshot {
  std::string arguments;  // "graphs/compare_tabletop.yaml --variants ..."
  std::string image;      // "images/compare-report.png", relative to docs/
};

DocScreenshot doc_screenshot() {
  const std::string doc = read_file(source_dir() / "docs/compare.md");
  const std::string marker = "<!-- screenshot of: facet compare ";
  const auto at = doc.find(marker);
  const auto close = doc.find(" -->", at);
  const auto picture = doc.find("](", close);
  if (at == std::string::npos || close == std::string::npos || picture == std::string::npos) {
    return {};
  }
  const auto image_end = doc.find(')', picture);
  return {doc.substr(at + marker.size(), close - at - marker.size()),
          doc.substr(picture + 2, image_end - picture - 2)};
}

// Shares of the picture's pixels: white (the page), near black (the label and depth images'
// background) and strongly coloured (the labels, the highlighted headline column).
struct PixelShares {
  double white = 0.0;
  double dark = 0.0;
  double coloured = 0.0;
};

PixelShares pixel_shares(const cv::Mat& bgr) {
  std::size_t white = 0;
  std::size_t dark = 0;
  std::size_t coloured = 0;
  for (int y = 0; y < bgr.rows; ++y) {
    for (int x = 0; x < bgr.cols; ++x) {
      const cv::Vec3b pixel = bgr.at<cv::Vec3b>(y, x);
      const int low = std::min({pixel[0], pixel[1], pixel[2]});
      const int high = std::max({pixel[0], pixel[1], pixel[2]});
      white += low >= 245 ? 1 : 0;
      dark += high <= 20 ? 1 : 0;
      coloured += high - low >= 80 ? 1 : 0;
    }
  }
  const double total = static_cast<double>(bgr.total());
  return {static_cast<double>(white) / total, static_cast<double>(dark) / total,
          static_cast<double>(coloured) / total};
}

TEST(CompareReportInChromium, LoadsEveryImageAndMakesTheDocsScreenshot) {
  const DocScreenshot doc = doc_screenshot();
  ASSERT_FALSE(doc.arguments.empty())
      << "docs/compare.md lost the '<!-- screenshot of: facet compare ... -->' comment above its "
         "screenshot";
  if (!have_chromium()) GTEST_SKIP() << "chromium is not installed (Debian package 'chromium')";

  // Run as the doc quotes it, from a folder where graphs/ and data/ are the repository's: the
  // report then shows the command line and the input as a reader would type them.
  TempDir dir("facet-screenshot");
  fs::create_directory_symlink(source_dir() / "graphs", dir / "graphs");
  fs::create_directory_symlink(source_dir() / "data", dir / "data");
  const auto result = run_cli_in(dir.path(), "compare " + doc.arguments);
  ASSERT_EQ(result.exit_code, 0) << doc.arguments << "\n" << result.out;
  const auto out = doc.arguments.find("--out ");
  ASSERT_NE(out, std::string::npos) << "the doc's command names no --out: " << doc.arguments;
  const fs::path report =
      dir / doc.arguments.substr(out + 6, doc.arguments.find(' ', out + 6) - out - 6) /
      "report.html";
  const std::string html = read_file(report);
  ASSERT_FALSE(html.empty()) << report;
  EXPECT_NE(html.find("<code>facet compare " + doc.arguments + "</code>"), std::string::npos);
  // No folder of the machine the test ran on (the input is named as the link from `dir`).
  EXPECT_EQ(html.find(source_dir().string()), std::string::npos);
  EXPECT_EQ(html.find(dir.path().string()), std::string::npos);

  const fs::path screenshot = dir / fs::path(doc.image).filename();
  const fs::path dom_file = dir / "dom.html";
  ASSERT_EQ(load_in_headless_chromium(
                report, dir / "profile", dom_file,
                "--hide-scrollbars --force-device-scale-factor=1 --window-size=" +
                    std::to_string(kScreenshotWidthPx) + "," + std::to_string(kScreenshotHeightPx) +
                    " --screenshot=" + shell_quote(screenshot.string())),
            0);

  // Every image decoded, and the tables are there.
  const std::string dom = read_file(dom_file);
  const std::size_t images = count_of(html, "<img ");
  EXPECT_GE(images, 4u);
  EXPECT_NE(dom.find("data-images-loaded=\"" + std::to_string(images) + "\""), std::string::npos)
      << images << " images; " << dom.substr(0, 600);
  EXPECT_NE(dom.find("<p class=\"headline\">Best "), std::string::npos);
  EXPECT_NE(dom.find("<table id=\"summary\">"), std::string::npos);
  EXPECT_GE(count_of(dom, "<table class=\"stages\">"), 2u);

  // The screenshot: the window's size, and the page with its images, not a blank or an error
  // page (one colour, or grey without the labels' colours).
  const cv::Mat picture = cv::imread(screenshot.string(), cv::IMREAD_COLOR);
  ASSERT_FALSE(picture.empty()) << screenshot << " is missing or no image";
  EXPECT_EQ(picture.cols, kScreenshotWidthPx);
  EXPECT_EQ(picture.rows, kScreenshotHeightPx);
  const PixelShares shares = pixel_shares(picture);
  EXPECT_GT(shares.white, 0.3) << "the page's white background";
  EXPECT_GT(shares.dark, 0.05) << "the black backgrounds of the depth and label images";
  EXPECT_GT(shares.coloured, 0.01) << "the labels' colours";
  EXPECT_LT(shares.white, 0.95);

  // scripts/update_compare_screenshot.sh: the doc's picture is this one.
  if (const char* copy_to = std::getenv("FACET_SCREENSHOT_DIR"); copy_to != nullptr) {
    const fs::path target = fs::path(copy_to) / screenshot.filename();
    fs::copy_file(screenshot, target, fs::copy_options::overwrite_existing);
    std::cout << "wrote " << target.string() << " (" << fs::file_size(target) << " bytes)\n";
  }
}

}  // namespace
}  // namespace facet::test
