#include "view/window_thread.hpp"

#include <chrono>
#include <opencv2/highgui.hpp>
#include <utility>

namespace facet::view {
namespace {

constexpr int kKeyEscape = 27;
// While no picture is due, the window still handles its events (redraws, keys) this often.
constexpr std::chrono::milliseconds kIdlePump{30};

bool is_close_key(int key) {
  return key == 'q' || key == 'Q' || key == kKeyEscape;
}

}  // namespace

WindowThread::WindowThread(std::string title, int wait_ms)
    : title_(std::move(title)), wait_ms_(wait_ms), thread_([this] { run(); }) {}

WindowThread::~WindowThread() {
  {
    const std::lock_guard lock(mutex_);
    stop_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

WindowThread::Outcome WindowThread::show(cv::Mat picture) {
  std::unique_lock lock(mutex_);
  pending_ = std::move(picture);
  shown_ = false;
  changed_.notify_all();
  changed_.wait(lock, [this] { return shown_; });
  return std::exchange(outcome_, Outcome{});
}

void WindowThread::run() {
  bool open = false;
  bool closed = false;  // by the user: never opened again
  std::unique_lock lock(mutex_);
  while (true) {
    changed_.wait_for(lock, kIdlePump, [this] { return stop_ || !pending_.empty(); });
    if (stop_) break;
    if (pending_.empty()) {
      // Idle: keep the window alive and listen for q/Esc.
      if (open) {
        lock.unlock();
        const int key = cv::waitKey(1);
        lock.lock();
        if (is_close_key(key)) {
          cv::destroyWindow(title_);
          open = false;
          closed = true;
          outcome_.closed_by_user = true;
        }
      }
      continue;
    }
    cv::Mat picture = std::move(pending_);
    pending_ = cv::Mat();
    lock.unlock();
    Outcome outcome;
    try {
      if (!open && !closed) {
        cv::namedWindow(title_, cv::WINDOW_AUTOSIZE);
        open = true;
      }
      if (open) {
        cv::imshow(title_, picture);
        if (is_close_key(cv::waitKey(wait_ms_))) {
          cv::destroyWindow(title_);
          open = false;
          closed = true;
          outcome.closed_by_user = true;
        }
      }
    } catch (const cv::Exception& error) {
      outcome.error = error.what();
      open = false;
    }
    lock.lock();
    outcome_.closed_by_user = outcome_.closed_by_user || outcome.closed_by_user;
    if (!outcome.error.empty()) outcome_.error = outcome.error;
    shown_ = true;
    changed_.notify_all();
  }
  lock.unlock();
  if (open) {
    try {
      cv::destroyWindow(title_);
      cv::waitKey(1);  // lets the toolkit take the window down
    } catch (const cv::Exception&) {
      // Closing is best effort: the display may already be gone.
    }
  }
}

}  // namespace facet::view
