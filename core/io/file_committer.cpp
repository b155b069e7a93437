#include "core/io/file_committer.h"

#include <exception>
#include <utility>

#include "core/io/atomic_write.h"

namespace lmc {

FileCommitter::FileCommitter(std::size_t max_pending_bytes)
    : max_pending_bytes_(max_pending_bytes), worker_([this] { run(); }) {}

FileCommitter::~FileCommitter() {
  (void)finish();
}

void FileCommitter::submit(std::filesystem::path path, std::string contents, std::string owner) {
  std::unique_lock lock(mutex_);
  // One file larger than the bound still goes through once the queue is empty.
  changed_.wait(lock,
                [&] { return closing_ || queue_.empty() || pending_bytes_ + contents.size() <= max_pending_bytes_; });
  if (closing_) {
    failures_.push_back({std::move(owner), path.string() + ": not written (the committer had already finished)"});
    return;
  }
  pending_bytes_ += contents.size();
  queue_.push_back({std::move(path), std::move(contents), std::move(owner)});
  changed_.notify_all();
}

std::vector<FileCommitter::Failure> FileCommitter::finish() {
  {
    std::lock_guard lock(mutex_);
    closing_ = true;
    changed_.notify_all();
  }
  if (worker_.joinable()) worker_.join();
  std::lock_guard lock(mutex_);
  return failures_;
}

void FileCommitter::run() {
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(lock, [&] { return closing_ || !queue_.empty(); });
    if (queue_.empty()) return;  // closing, and everything written
    Pending file = std::move(queue_.front());
    queue_.pop_front();
    lock.unlock();
    std::string error;
    try {
      write_file_atomically(file.path, file.contents);
    } catch (const std::exception& e) {
      error = e.what();
    }
    lock.lock();
    pending_bytes_ -= file.contents.size();
    if (!error.empty()) failures_.push_back({std::move(file.owner), std::move(error)});
    changed_.notify_all();
  }
}

}  // namespace lmc
