#pragma once
// Files made durable on a thread of their own. Each file still goes through
// write_file_atomically (temporary file, fsync, rename), but the threads that compute the next
// trial hand their finished files over instead of waiting for the disk: on a machine with few cores
// the fsyncs of a batch's outputs would otherwise stall a core that has trials to compute.
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <filesystem>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace lmc {

class FileCommitter {
 public:
  // A file that could not be written: the error names the path, `owner` says whose file it was
  // (a trial's name) so the caller can mark that work as failed.
  struct Failure {
    std::string owner;
    std::string message;
  };

  // `max_pending_bytes` bounds what waits in memory: submit() blocks while more than that is queued.
  explicit FileCommitter(std::size_t max_pending_bytes = std::size_t{256} << 20);
  ~FileCommitter();
  FileCommitter(const FileCommitter&) = delete;
  FileCommitter& operator=(const FileCommitter&) = delete;

  // Safe from any thread. Files are written in the order they were submitted.
  void submit(std::filesystem::path path, std::string contents, std::string owner);

  // Waits until every submitted file is on disk (or has failed) and returns the failures in the
  // order the files were submitted. After finish() the committer takes no more files.
  std::vector<Failure> finish();

 private:
  struct Pending {
    std::filesystem::path path;
    std::string contents;
    std::string owner;
  };
  void run();

  std::size_t max_pending_bytes_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Pending> queue_;
  std::size_t pending_bytes_ = 0;
  bool closing_ = false;
  std::vector<Failure> failures_;
  std::thread worker_;
};

}  // namespace lmc
