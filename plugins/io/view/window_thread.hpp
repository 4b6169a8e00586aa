#pragma once
// io.view's window and the one thread that drives it. OpenCV's highgui (Qt on Debian) must be
// called from a single thread for the whole life of a window, but an executor may call a stage
// from any of its worker threads and close it from another: so the window lives in a thread of
// its own, and the stage hands it pictures. (The one thread a stage starts itself: it does no
// processing, it only keeps the window on screen and answers its keys.)

#include <condition_variable>
#include <mutex>
#include <opencv2/core/mat.hpp>
#include <string>
#include <thread>

namespace facet::view {

class WindowThread {
 public:
  WindowThread(std::string title, int wait_ms);
  ~WindowThread();  // takes the window down and joins the thread
  WindowThread(const WindowThread&) = delete;
  WindowThread& operator=(const WindowThread&) = delete;

  struct Outcome {
    bool closed_by_user = false;  // q or Esc: the window is gone
    std::string error;            // what OpenCV reported when it could not show the window
  };

  // Shows `picture` (CV_8UC3) and returns once it is on screen and the window has waited
  // wait_ms for a key; tells what happened since the last call.
  Outcome show(cv::Mat picture);

 private:
  void run();

  const std::string title_;
  const int wait_ms_;
  std::mutex mutex_;
  std::condition_variable changed_;
  cv::Mat pending_;  // the picture handed over, empty once taken
  bool shown_ = true;
  bool stop_ = false;
  Outcome outcome_;
  std::thread thread_;  // last: started once everything it uses exists
};

}  // namespace facet::view
