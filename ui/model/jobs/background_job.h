#pragma once
// One small generic wrapper for long-running work on a std::jthread (docs/architecture.md).
//
// * start() takes a work function that owns its inputs (copy them into the lambda); the UI keeps
//   nothing the worker can see except this channel.
// * status() is an atomic: Starting, Running, Completed, Cancelled, Failed. The thread's entry
//   point catches every exception and records it as Failed with its message.
// * Progress goes through a locked queue of small report structs (drain_reports(), for history
//   such as the convergence plot) and two atomics done/total plus a stage name (for bar and ETA).
// * cancel() asks the worker to stop; the destructor asks and joins (jthread). Work functions must
//   check the stop token often.
// * The result is stored when the work returns. If a stop was requested by then, the status is
//   Cancelled (the result, if any, is the best-so-far).
#include <atomic>
#include <chrono>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <stop_token>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace lmc::ui {

enum class JobState : int { kIdle = 0, kStarting, kRunning, kCompleted, kCancelled, kFailed };
const char* job_state_name(JobState s);
inline bool job_finished(JobState s) {
  return s == JobState::kCompleted || s == JobState::kCancelled || s == JobState::kFailed;
}

// What a worker may touch.
template <class Report>
class JobChannel {
 public:
  void report(Report r) {
    std::lock_guard lock(mutex_);
    reports_.push_back(std::move(r));
  }
  void set_progress(long long done, long long total) {
    total_.store(total);
    done_.store(done);
  }
  void set_stage(std::string stage) {
    std::lock_guard lock(mutex_);
    stage_ = std::move(stage);
  }

  std::vector<Report> drain() {
    std::lock_guard lock(mutex_);
    std::vector<Report> out;
    out.swap(reports_);
    return out;
  }
  std::string stage() const {
    std::lock_guard lock(mutex_);
    return stage_;
  }
  long long done() const { return done_.load(); }
  long long total() const { return total_.load(); }

 private:
  mutable std::mutex mutex_;
  std::vector<Report> reports_;
  std::string stage_;
  std::atomic<long long> done_{0}, total_{0};
};

// Workers that were asked to stop but may still be finishing their current chunk. reap() joins
// those that have returned (never blocks); the destructor joins the rest.
class JobGraveyard {
 public:
  void add(std::jthread thread, std::function<bool()> finished) {
    entries_.push_back({std::move(thread), std::move(finished)});
  }
  void reap();
  size_t size() const { return entries_.size(); }

 private:
  struct Entry {
    std::jthread thread;
    std::function<bool()> finished;
  };
  std::vector<Entry> entries_;
};

template <class Result, class Report>
class BackgroundJob {
 public:
  using Work = std::function<Result(std::stop_token, JobChannel<Report>&)>;

  BackgroundJob() = default;
  ~BackgroundJob() { cancel_and_join(); }
  BackgroundJob(const BackgroundJob&) = delete;
  BackgroundJob& operator=(const BackgroundJob&) = delete;

  // Starts `work`; a job still running is cancelled and joined first.
  void start(Work work) {
    cancel_and_join();
    shared_ = std::make_shared<Shared>();
    started_at_ = std::chrono::steady_clock::now();
    shared_->state.store(JobState::kStarting);
    thread_ = std::jthread([s = shared_, w = std::move(work)](std::stop_token stop) {
      s->state.store(JobState::kRunning);
      try {
        Result r = w(stop, s->channel);
        {
          std::lock_guard lock(s->mutex);
          s->result = std::make_shared<const Result>(std::move(r));
        }
        s->state.store(stop.stop_requested() ? JobState::kCancelled : JobState::kCompleted);
      } catch (const std::exception& e) {
        std::lock_guard lock(s->mutex);
        s->error = e.what();
        s->state.store(JobState::kFailed);
      } catch (...) {
        std::lock_guard lock(s->mutex);
        s->error = "unknown error";
        s->state.store(JobState::kFailed);
      }
    });
  }

  void cancel() {
    if (thread_.joinable()) thread_.request_stop();
  }
  void cancel_and_join() {
    if (thread_.joinable()) {
      thread_.request_stop();
      thread_.join();
    }
  }
  // Detaches the running work into `graveyard` (asked to stop, joined when the graveyard is
  // cleaned) so a restart never waits for the old worker: used by restartable jobs.
  void abandon_into(JobGraveyard& graveyard) {
    if (thread_.joinable()) {
      thread_.request_stop();
      graveyard.add(std::move(thread_), [s = shared_] { return job_finished(s->state.load()); });
    }
    shared_.reset();
  }

  JobState state() const { return shared_ ? shared_->state.load() : JobState::kIdle; }
  bool running() const {
    const JobState s = state();
    return s == JobState::kStarting || s == JobState::kRunning;
  }
  std::vector<Report> drain_reports() { return shared_ ? shared_->channel.drain() : std::vector<Report>{}; }
  std::shared_ptr<const Result> result() const {
    if (!shared_) return nullptr;
    std::lock_guard lock(shared_->mutex);
    return shared_->result;
  }
  std::string error() const {
    if (!shared_) return {};
    std::lock_guard lock(shared_->mutex);
    return shared_->error;
  }
  std::string stage() const { return shared_ ? shared_->channel.stage() : std::string(); }
  long long done() const { return shared_ ? shared_->channel.done() : 0; }
  long long total() const { return shared_ ? shared_->channel.total() : 0; }
  double fraction() const {
    const long long t = total();
    return t > 0 ? static_cast<double>(done()) / static_cast<double>(t) : 0.0;
  }
  double elapsed_seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - started_at_).count();
  }
  // Remaining time from done/total and the steady clock; nullopt until there is progress.
  std::optional<double> eta_seconds() const {
    const double f = fraction();
    if (!running() || f <= 0.0) return std::nullopt;
    return elapsed_seconds() * (1.0 - f) / f;
  }

 private:
  struct Shared {
    std::atomic<JobState> state{JobState::kIdle};
    JobChannel<Report> channel;
    std::mutex mutex;
    std::shared_ptr<const Result> result;
    std::string error;
  };
  std::shared_ptr<Shared> shared_;
  std::chrono::steady_clock::time_point started_at_{};
  std::jthread thread_;  // last member: destroyed (joined) first
};

}  // namespace lmc::ui
