// Recorder: loss-free recording, unplug, disk error, flushing, sidecar.
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <stdexcept>
#include <thread>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/io/layout_json.h"
#include "core/io/lmc_recording.h"
#include "devices/device_hub.h"
#include "devices/record/clock_alignment.h"
#include "devices/record/recorder.h"
#include "devices/record/trial_name.h"
#include "devices/sim/sim_rig.h"
#include "tests/devices/sim/sim_fixtures.h"
#include "tests/support/full_disk_sink.h"
#include "tests/support/reference_data.h"
#include "tests/support/test_recorder.h"

namespace lmc::devices {
namespace recorder_test {

using sim_fixtures::paper_initial;

std::map<int, std::int64_t> rows_per_device(const std::filesystem::path& file) {
  std::map<int, std::int64_t> out;
  for (const auto& r : read_lmc_recording(file).rows) ++out[r.device_id];
  return out;
}

// The same count from the text alone (first field of every row after the header), for the large
// file of the loss-free test where a full parse would dominate the test's time.
std::map<int, std::int64_t> rows_per_device_by_line(const std::filesystem::path& file) {
  std::map<int, std::int64_t> out;
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line.rfind("Device ID\t", 0), 0u) << "raw header expected";
  while (std::getline(in, line)) {
    EXPECT_FALSE(line.empty());
    ++out[std::stoi(line.substr(0, line.find('\t')))];
  }
  return out;
}

nlohmann::json read_json(const std::filesystem::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

// Offers device 1's frame `i`: frame id i, stamped i ms on the device clock, received at host
// time i ns.
bool offer_frame(Recorder& rec, int i, bool may_wait) {
  HandFrame f;
  f.device_id = 1;
  f.frame_id = i;
  f.timestamp_us = 1000 * i;
  return rec.offer(f, i, may_wait);
}

// Records the whole of `trial` into `rec`, started here, and stops it: the trial is played into
// the hub from the calling thread, as fast as it goes.
RecorderStatus record_trial(const SimTrial& trial, DeviceHub& hub, Recorder& rec) {
  rec.start();
  hub.set_consumer(&rec);
  for (const auto& e : trial.events) {
    if (e.is_frame)
      hub.on_frame(e.frame);
    else
      hub.on_device_event(e.event);
  }
  hub.set_consumer(nullptr);
  return rec.stop(hub.serial_to_slot());
}

TEST(TrialName, OnlySafeNamesBecomeFileNames) {
  EXPECT_EQ(validate_trial_name("Naiv_Static101"), "");
  EXPECT_EQ(validate_trial_name("s01-opt-index_3"), "");
  for (const std::string& bad :
       std::vector<std::string>{"", "../etc", "a b", "x/y", "%s%n", "-rf", "trial.txt", "é", std::string(65, 'a')})
    EXPECT_NE(validate_trial_name(bad), "") << bad;
  EXPECT_THROW(checked_trial_files("/tmp", "../../x"), Error);
  const auto p = checked_trial_files("/data", "Naiv_Static101");
  EXPECT_EQ(p.recording, std::filesystem::path("/data/LMC_Naiv_Static101.raw.txt"));
  EXPECT_EQ(p.truth_trc, std::filesystem::path("/data/Naiv_Static101.trc"));
}

TEST(Recorder, FourDevicesAt120HzFor60sLoseNoFrame) {
  SimConfig sim;
  sim.seed = 7;
  sim.rate_min_hz = sim.rate_max_hz = 120.0;
  // A still hand with visibility off keeps the 28 800-frame generation quick; not under test here.
  sim.fov_test = sim.occlusion = false;
  sim.sway_mm = 0;
  const SimTrial trial = generate_sim_trial(paper_initial(), sim, 60.0);
  std::int64_t emitted = 0;
  for (const auto& [serial, n] : trial.frame_counts()) emitted += n;
  ASSERT_NEAR(static_cast<double>(emitted), 4 * 120 * 60, 8);

  HubOptions ho;
  ho.backpressure = true;  // simulated time: the producer is not hardware-paced
  DeviceHub hub(paper_initial(), ho);
  RecorderConfig rc = test::recorder_config(test::scratch_dir("rec_lossfree"), "lossfree");
  rc.backend = "sim";
  rc.queue_capacity = 1024;  // small on purpose: the producer outruns the disk and must wait
  Recorder rec(rc);
  const RecorderStatus st = record_trial(trial, hub, rec);
  ASSERT_EQ(st.state, RecorderState::kStopped) << st.error;
  EXPECT_EQ(st.frames_dropped, 0);
  EXPECT_EQ(st.frames_written, emitted);

  const auto rows = rows_per_device_by_line(rec.paths().recording);
  const auto counts = trial.frame_counts();
  const auto map = hub.serial_to_slot();
  ASSERT_EQ(map.size(), 4u);
  for (const auto& [serial, slot] : map) {
    const int id = paper_initial().find_slot(slot) + 1;
    std::int64_t n = 0;
    for (const auto& [s, c] : counts)
      if (s == serial) n = c;
    EXPECT_EQ(rows.at(id), n) << slot;
  }
  const auto side = read_json(rec.paths().sidecar);
  EXPECT_EQ(side["status"], "completed");
  EXPECT_EQ(side["frames_written"].get<std::int64_t>(), emitted);
  EXPECT_EQ(side["frames_dropped"].get<std::int64_t>(), 0);
  ASSERT_EQ(side["devices"].size(), 4u);
  for (const auto& d : side["devices"]) {
    EXPECT_EQ(d["frames_written"].get<std::int64_t>(), rows.at(d["device_id"].get<int>()));
    EXPECT_TRUE(d["gaps"].empty());
    EXPECT_EQ(d["frame_id_gaps"], 0);
  }
}

TEST(Recorder, ConcurrentRealtimeProducersWithRoomLoseNothing) {
  RecorderConfig rc = test::recorder_config(test::scratch_dir("rec_mt"), "mt");
  rc.queue_capacity = 20000;
  Recorder rec(rc);
  rec.start();
  constexpr int kPerDevice = 3000;
  std::vector<std::thread> producers;
  std::atomic<int> refused{0};
  for (int d = 1; d <= 4; ++d) {
    producers.emplace_back([&, d] {
      for (int i = 0; i < kPerDevice; ++i) {
        HandFrame f;
        f.device_id = d;
        f.frame_id = i;
        f.timestamp_us = 1000 + i * 8333LL;
        f.hand_present = (i % 3) != 0;
        for (int p = 0; p < kNumHandPoints; ++p) f.point(p) = Vec3(p, d, i);
        if (!rec.offer(f, i, false)) ++refused;
      }
    });
  }
  for (auto& t : producers) t.join();
  const auto st = rec.stop();
  EXPECT_EQ(refused.load(), 0);
  const auto rows = rows_per_device(rec.paths().recording);
  for (int d = 1; d <= 4; ++d) EXPECT_EQ(rows.at(d), kPerDevice);
  // Each device's rows stay in its own order.
  std::map<int, std::int64_t> last;
  for (const auto& r : read_lmc_recording(rec.paths().recording).rows) {
    if (last.count(r.device_id)) {
      EXPECT_EQ(r.frame_id, last[r.device_id] + 1);
    }
    last[r.device_id] = r.frame_id;
  }
  EXPECT_EQ(st.frames_written, 4 * kPerDevice);
}

TEST(Recorder, UnpluggedDeviceLeavesTheFileIntactWithTheGapRecorded) {
  SimConfig sim;
  sim.seed = 3;
  sim.unplugs.push_back({"LMC2", 1.0, 0.8});
  const SimTrial trial = generate_sim_trial(paper_initial(), sim, 3.0);
  HubOptions ho;
  ho.backpressure = true;
  DeviceHub hub(paper_initial(), ho);
  RecorderConfig rc = test::recorder_config(test::scratch_dir("rec_unplug"), "unplug");
  Recorder rec(rc);
  const RecorderStatus st = record_trial(trial, hub, rec);
  ASSERT_EQ(st.state, RecorderState::kStopped) << st.error;

  // The operator is told.
  bool told = false;
  for (const auto& m : hub.take_messages())
    told = told || (m.find("LMC2") != std::string::npos && m.find("disconnected") != std::string::npos);
  EXPECT_TRUE(told);
  // The file holds every frame of every device, LMC2 included before and after the gap.
  const auto rows = rows_per_device(rec.paths().recording);
  std::int64_t emitted = 0;
  for (const auto& [s, n] : trial.frame_counts()) emitted += n;
  std::int64_t written = 0;
  for (const auto& [id, n] : rows) written += n;
  EXPECT_EQ(written, emitted);
  const auto side = read_json(rec.paths().sidecar);
  const nlohmann::json* lmc2 = nullptr;
  for (const auto& d : side["devices"])
    if (d["slot"] == "LMC2") lmc2 = &d;
  ASSERT_NE(lmc2, nullptr);
  ASSERT_EQ((*lmc2)["gaps"].size(), 1u);
  const double gap_ms = (*lmc2)["gaps"][0]["duration_ms"].get<double>();
  EXPECT_GT(gap_ms, 750.0);
  EXPECT_LT(gap_ms, 950.0);
  ASSERT_EQ((*lmc2)["disconnects"].size(), 1u);
  EXPECT_TRUE((*lmc2)["disconnects"][0].contains("reconnected_host_time_utc"));
  for (const auto& d : side["devices"])
    if (d["slot"] != "LMC2") {
      EXPECT_TRUE(d["gaps"].empty()) << d["slot"];
    }
}

// Writes to the real file until `limit` bytes, then fails like a full disk.
using test::FullDiskSink;

TEST(Recorder, DiskFullStopsTheTrialWithAClearMessageAndKeepsWhatWasWritten) {
  RecorderConfig rc = test::recorder_config(test::scratch_dir("rec_full"), "full");
  rc.flush_interval_ms = 20;
  rc.open_sink = [](const std::filesystem::path& p) {
    return std::make_unique<FullDiskSink>(open_file_sink(p), 64 * 1024);
  };
  Recorder rec(rc);
  rec.start();
  SimConfig sim;
  const SimTrial trial = generate_sim_trial(paper_initial(), sim, 20.0);
  int offered = 0;
  for (const auto& e : trial.events) {
    if (!e.is_frame) continue;
    HandFrame f = e.frame.frame;
    rec.offer(f, e.frame.host_receive_ns, true);
    ++offered;
    if (offered % 200 == 0) std::this_thread::sleep_for(std::chrono::milliseconds(30));
    if (rec.failed()) break;
  }
  const auto st = rec.stop();
  ASSERT_EQ(st.state, RecorderState::kFailed);
  EXPECT_NE(st.error.find("No space left on device"), std::string::npos) << st.error;
  EXPECT_NE(st.error.find("LMC_full.raw.txt"), std::string::npos) << st.error;
  EXPECT_EQ(std::filesystem::file_size(rec.paths().recording), 64u * 1024u);
  // What was written is still a readable recording (the cut last line is dropped with a warning).
  const LmcRecording back = read_lmc_recording(rec.paths().recording);
  EXPECT_GT(back.rows.size(), 10u);
  const auto side = read_json(rec.paths().sidecar);
  EXPECT_EQ(side["status"], "failed");
  EXPECT_NE(side["error"].get<std::string>().find("No space left"), std::string::npos);
  // The counts describe the file as it is: exactly its complete rows, per device too.
  EXPECT_EQ(side["frames_written"].get<size_t>(), back.rows.size());
  EXPECT_EQ(st.frames_written, static_cast<std::int64_t>(back.rows.size()));
  std::map<int, std::int64_t> per_device;
  for (const auto& r : back.rows) ++per_device[r.device_id];
  for (const auto& d : side["devices"])
    EXPECT_EQ(d["frames_written"].get<std::int64_t>(), per_device[d["device_id"].get<int>()]) << d["slot"];
}

// A sink whose write throws once `throw_after` bytes reached the file: stands for anything the
// writer thread did not expect (a formatting error, memory exhausted).
class ThrowingSink final : public ByteSink {
 public:
  ThrowingSink(std::unique_ptr<ByteSink> inner, std::uint64_t throw_after)
      : inner_(std::move(inner)), throw_after_(throw_after) {}
  bool write(std::string_view data) override {
    if (inner_->bytes_written() >= throw_after_) throw std::runtime_error("sink exploded");
    return inner_->write(data);
  }
  bool sync() override { return inner_->sync(); }
  bool close() override { return inner_->close(); }
  std::string error() const override { return inner_->error(); }
  std::uint64_t bytes_written() const override { return inner_->bytes_written(); }

 private:
  std::unique_ptr<ByteSink> inner_;
  std::uint64_t throw_after_;
};

TEST(Recorder, AnExceptionInTheWriterFailsTheTrialInsteadOfEndingTheProgram) {
  RecorderConfig rc = test::recorder_config(test::scratch_dir("rec_throw"), "throws");
  rc.flush_interval_ms = 20;
  rc.open_sink = [](const std::filesystem::path& p) { return std::make_unique<ThrowingSink>(open_file_sink(p), 1); };
  Recorder rec(rc);
  rec.start();  // the header (the first bytes) goes through; the first rows throw
  int offered = 0;
  for (int i = 1; i <= 5000 && !rec.failed(); ++i) {
    offer_frame(rec, i, true);
    ++offered;
    if (i % 100 == 0) std::this_thread::sleep_for(std::chrono::milliseconds(25));
  }
  ASSERT_TRUE(rec.failed()) << "the writer's exception never reached the status";
  // Frames offered after the failure are refused and counted, never queued for a dead writer.
  EXPECT_FALSE(offer_frame(rec, offered + 1, true));
  const auto st = rec.stop();
  ASSERT_EQ(st.state, RecorderState::kFailed);
  EXPECT_NE(st.error.find("the writer failed (sink exploded)"), std::string::npos) << st.error;
  EXPECT_EQ(st.frames_written, 0);
  EXPECT_GE(st.frames_dropped, 1);
  const auto side = read_json(rec.paths().sidecar);
  EXPECT_EQ(side["status"], "failed");
  EXPECT_NE(side["error"].get<std::string>().find("sink exploded"), std::string::npos);
  // The file holds its header and is still a readable (empty) recording.
  EXPECT_TRUE(read_lmc_recording(rec.paths().recording).rows.empty());
}

TEST(Recorder, FileSinkReportsARealDeviceFullError) {
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "/dev/full is absent on this system";
  auto sink = open_file_sink("/dev/full");
  EXPECT_FALSE(sink->write("x\n"));
  EXPECT_NE(sink->error().find("No space left on device"), std::string::npos) << sink->error();
}

TEST(Recorder, FileSizeLimitIsAClearWriteErrorNotAKill) {
  // ulimit -f: with SIGXFSZ ignored (as lmc and lmc-workbench do at start) the write fails with
  // EFBIG and the sink says what happened. Run in a child: the limit is process-wide.
  const auto dir = test::scratch_dir("rec_fsize");
  const auto file = dir / "limited.txt";
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    rlimit lim{};
    lim.rlim_cur = 4096;
    lim.rlim_max = 4096;
    if (::setrlimit(RLIMIT_FSIZE, &lim) != 0) ::_exit(10);
    auto sink = open_file_sink(file);
    if (!sink->write(std::string(1000, 'a'))) ::_exit(11);  // fits
    if (sink->write(std::string(8000, 'b'))) ::_exit(12);   // must fail, not kill
    const std::string e = sink->error();
    if (e.find("File too large") == std::string::npos) ::_exit(13);
    if (e.find("ulimit -f") == std::string::npos) ::_exit(14);
    if (e.find("limited.txt") == std::string::npos) ::_exit(15);
    ::_exit(0);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  EXPECT_EQ(WEXITSTATUS(status), 0) << "10 setrlimit, 11 first write, 12 no failure, 13-15 message";
  EXPECT_EQ(std::filesystem::file_size(file), 4096u) << "what fitted is kept";
}

// Go is an instant the engine takes a moment before it opens the window; a frame received after
// that instant but offered before the window opened belongs to the trial all the same.
TEST(Recorder, AFrameOfferedJustBeforeTheWindowOpensButReceivedAfterGoIsWritten) {
  RecorderConfig rc = test::recorder_config(test::scratch_dir("rec_go_race"), "go_race");
  rc.wait_for_go = true;
  Recorder rec(rc);
  rec.start();
  HandFrame f;
  f.device_id = 1;
  // Received at 100…104 ms; go is taken at 102 ms and the window opened after all five arrived.
  for (int i = 0; i < 5; ++i) {
    f.frame_id = i;
    f.timestamp_us = 100'000 + 1000 * i;
    rec.offer(f, 100'000'000 + 1'000'000 * i, false);
  }
  rec.open_window(102'000'000, 103'500'000);
  f.frame_id = 5;
  f.timestamp_us = 105'000;
  rec.offer(f, 105'000'000, false);  // after the end
  rec.stop();
  const LmcRecording back = read_lmc_recording(rec.paths().recording);
  ASSERT_EQ(back.rows.size(), 2u) << "received at 102 and 103 ms: inside [go, end)";
  EXPECT_EQ(back.rows[0].frame_id, 2);
  EXPECT_EQ(back.rows[1].frame_id, 3);
  const auto side = read_json(rec.paths().sidecar);
  EXPECT_EQ(side["trial_window"]["frames_before_go"], 2);
  EXPECT_EQ(side["trial_window"]["frames_after_end"], 2);
}

TEST(Recorder, StopWithAReasonMarksTheTrialAborted) {
  RecorderConfig rc = test::recorder_config(test::scratch_dir("rec_abort"), "abort");
  Recorder rec(rc);
  rec.start();
  for (int i = 0; i < 3; ++i) offer_frame(rec, i, false);
  const auto st = rec.stop({}, "Vicon trigger: sending to 127.0.0.1:9 failed: Connection refused");
  EXPECT_EQ(st.state, RecorderState::kAborted);
  EXPECT_STREQ(recorder_state_name(st.state), "aborted");
  EXPECT_NE(st.error.find("Connection refused"), std::string::npos);
  const auto side = read_json(rec.paths().sidecar);
  EXPECT_EQ(side["status"], "aborted");
  EXPECT_EQ(side["error"], "Vicon trigger: sending to 127.0.0.1:9 failed: Connection refused");
  EXPECT_EQ(side["frames_written"], 3) << "the rows written are kept";
  EXPECT_EQ(read_lmc_recording(rec.paths().recording).rows.size(), 3u);
}

TEST(Recorder, AWriteErrorStaysFailedWhateverTheAbortReason) {
  RecorderConfig rc = test::recorder_config(test::scratch_dir("rec_fail_abort"), "fa");
  rc.flush_interval_ms = 10;
  // Room for the header and a few short rows.
  const size_t limit = lmc_recording_header(RecordingKind::kRaw).size() + 100;
  rc.open_sink = [limit](const std::filesystem::path& p) {
    return std::make_unique<FullDiskSink>(open_file_sink(p), limit);
  };
  Recorder rec(rc);
  rec.start();
  HandFrame f;
  f.device_id = 1;
  for (int i = 0; i < 50 && !rec.failed(); ++i) {
    f.frame_id = i;
    rec.offer(f, i, true);
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (!rec.failed() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ASSERT_TRUE(rec.failed());
  const auto st = rec.stop({}, "something else went wrong later");
  EXPECT_EQ(st.state, RecorderState::kFailed);
  const auto side = read_json(rec.paths().sidecar);
  EXPECT_EQ(side["status"], "failed");
  EXPECT_NE(side["error"].get<std::string>().find("No space left"), std::string::npos) << side["error"];
}

// The output folder removed mid-trial once went unnoticed (the trial ran on into a deleted
// file); the recorder now notices within its flush interval and fails with that cause.
TEST(Recorder, OutputFolderDeletedMidTrialFailsTheTrial) {
  const auto dir = test::scratch_dir("rec_folder_gone") / "trial_folder";
  RecorderConfig rc = test::recorder_config(dir, "gone");
  rc.flush_interval_ms = 20;
  Recorder rec(rc);
  rec.start();
  for (int i = 0; i < 5; ++i) offer_frame(rec, i, true);
  std::filesystem::remove_all(dir);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);  // a hang guard only
  for (int i = 5; !rec.failed() && std::chrono::steady_clock::now() < deadline; ++i) {
    offer_frame(rec, i, true);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_TRUE(rec.failed());
  const auto st = rec.stop();
  EXPECT_EQ(st.state, RecorderState::kFailed);
  EXPECT_NE(st.error.find("LMC_gone.raw.txt was deleted while recording"), std::string::npos) << st.error;
  // The final sidecar cannot be written into a folder that is gone: said too, not swallowed.
  EXPECT_NE(st.error.find("cannot write the session sidecar"), std::string::npos) << st.error;
}

// Writes nowhere and never fails: the recording "file" is fine, only the sidecar can fail.
class MemorySink final : public ByteSink {
 public:
  bool write(std::string_view data) override {
    bytes_ += data.size();
    return true;
  }
  bool sync() override { return true; }
  bool close() override { return true; }
  std::string error() const override { return {}; }
  std::uint64_t bytes_written() const override { return bytes_; }

 private:
  std::uint64_t bytes_ = 0;
};

// On a 64 KB tmpfs the raw file was fine but the final sidecar could not be written; it
// stayed "recording" with 0 frames and nothing said so.
TEST(Recorder, ASidecarWriteErrorIsReportedEvenAfterAnotherError) {
  for (const std::string abort_reason : {"", "the Vicon trigger failed"}) {
    const auto dir = test::scratch_dir("rec_sidecar_fail") / "trial_folder";
    RecorderConfig rc = test::recorder_config(dir, "side");
    rc.open_sink = [](const std::filesystem::path&) { return std::make_unique<MemorySink>(); };
    Recorder rec(rc);
    rec.start();
    HandFrame f;
    f.device_id = 1;
    rec.offer(f, 1, true);
    std::filesystem::remove_all(dir);  // the sidecar's temporary file cannot be created now
    const auto st = rec.stop({}, abort_reason);
    EXPECT_EQ(st.state, RecorderState::kFailed) << abort_reason;
    EXPECT_NE(st.error.find("cannot write the session sidecar"), std::string::npos) << st.error;
    EXPECT_NE(st.error.find("LMC_side.session.json"), std::string::npos) << st.error;
    EXPECT_NE(st.error.find("still says 'recording'"), std::string::npos) << st.error;
    if (!abort_reason.empty()) {
      EXPECT_EQ(st.error.rfind(abort_reason, 0), 0u) << "the first cause stays first: " << st.error;
    }
  }
}

TEST(ClockAlignment, EachDeviceClockIsExtrapolatedToTheViconInstant) {
  HubSnapshot snap;
  DeviceStatus a;
  a.serial = "SIM-1";
  a.slot = "LMC1";
  a.slot_index = 0;
  a.frames_received = 10;
  a.latest_host_receive_ns = 5'000'000'000;
  HandFrame fa;
  for (auto& p : fa.points) p.setZero();  // Eigen leaves them unset; copying them would read garbage
  fa.frame_id = 77;
  fa.timestamp_us = 1'000'000;
  a.latest = fa;
  DeviceStatus silent;  // assigned, no frame yet
  silent.serial = "SIM-2";
  silent.slot = "LMC2";
  silent.slot_index = 1;
  DeviceStatus stray;  // unassigned: not recorded, not aligned
  stray.serial = "X";
  stray.frames_received = 3;
  stray.latest_host_receive_ns = 4'000'000'000;
  stray.latest = fa;
  snap.devices = {a, silent, stray};
  const auto j = clock_alignment_json(snap, "CaptureStart sent", 5'010'000'000, 1234, "2026-11-22T00:00:00.000Z");
  EXPECT_EQ(j["event"], "CaptureStart sent");
  EXPECT_EQ(j["packet_id"], 1234);
  EXPECT_EQ(j["host_ns"], 5'010'000'000);
  ASSERT_EQ(j["devices"].size(), 2u);
  const auto& d = j["devices"][0];
  EXPECT_EQ(d["device_id"], 1);
  EXPECT_EQ(d["slot"], "LMC1");
  EXPECT_EQ(d["serial"], "SIM-1");
  EXPECT_EQ(d["latest_frame_id"], 77);
  EXPECT_EQ(d["latest_timestamp_us"], 1'000'000);
  EXPECT_EQ(d["latest_host_receive_ns"], 5'000'000'000);
  EXPECT_EQ(d["host_ns_since_latest"], 10'000'000);
  EXPECT_EQ(d["device_clock_at_event_us"], 1'010'000);  // 10 ms after the latest frame
  EXPECT_EQ(d["device_clock_method"], "extrapolated");  // no clock read: the source has none
  EXPECT_EQ(j["devices"][1]["slot"], "LMC2");
  EXPECT_TRUE(j["devices"][1]["latest_timestamp_us"].is_null());
  EXPECT_TRUE(j["devices"][1]["device_clock_at_event_us"].is_null());
}

TEST(ClockAlignment, HubSnapshotCarriesTheLatestReceiveTime) {
  Layout l = paper_initial();
  HubOptions o;
  std::int64_t now = 7'000'000'000;
  o.clock = [&] { return now; };
  DeviceHub hub(l, o);
  DeviceEvent e;
  e.kind = DeviceEventKind::kAppeared;
  e.info.serial = "S1";
  hub.on_device_event(e);
  SourceFrame f;
  f.serial = "S1";
  f.host_receive_ns = 6'900'000'000;
  f.frame.timestamp_us = 123'456;
  hub.on_frame(f);
  const auto snap = hub.snapshot();
  ASSERT_FALSE(snap.devices.empty());
  EXPECT_EQ(snap.devices[0].latest_host_receive_ns, 6'900'000'000);
  const auto j = clock_alignment_json(snap, "CaptureStart received", now, 1, "");
  EXPECT_EQ(j["devices"][0]["device_clock_at_event_us"], 123'456 + 100'000);
}

TEST(Recorder, RowsReachTheFileWhileRecording) {
  RecorderConfig rc = test::recorder_config(test::scratch_dir("rec_flush"), "flush");
  rc.flush_interval_ms = 50;
  Recorder rec(rc);
  rec.start();
  const auto header_size = std::filesystem::file_size(rec.paths().recording);
  HandFrame f;
  f.device_id = 1;
  for (int i = 0; i < 5; ++i) {
    f.frame_id = i;
    rec.offer(f, i, false);
  }
  // Without stop(): the writer pushes its buffer within the flush interval (≤ 1 s by contract).
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (std::filesystem::file_size(rec.paths().recording) == header_size &&
         std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_EQ(read_lmc_recording(rec.paths().recording).rows.size(), 5u);
  // The sidecar already exists and says the trial is in progress.
  EXPECT_EQ(read_json(rec.paths().sidecar)["status"], "recording");
  rec.stop();
  EXPECT_EQ(read_json(rec.paths().sidecar)["status"], "completed");
}

TEST(Recorder, SidecarDescribesTheSession) {
  RecorderConfig rc = test::recorder_config(test::scratch_dir("rec_side"), "side");
  rc.backend = "sim";
  Recorder rec(rc);
  rec.start();
  rec.note_vicon_packet({{"type", "CaptureStart"}, {"packet_id", 5}});
  rec.stop({{"SIM-1", "LMC1"}});
  const auto j = read_json(rec.paths().sidecar);
  EXPECT_EQ(j["trial"], "side");
  EXPECT_EQ(j["backend"], "sim");
  EXPECT_EQ(j["serial_to_slot"]["SIM-1"], "LMC1");
  EXPECT_EQ(j["layout"]["name"], "paper-initial");
  EXPECT_EQ(j["software"]["version"], LMC_VERSION);
  EXPECT_EQ(j["vicon_packets"][0]["packet_id"], 5);
  EXPECT_FALSE(j["host_start_utc"].get<std::string>().empty());
  EXPECT_FALSE(j["host_stop_utc"].get<std::string>().empty());
  EXPECT_EQ(j["recording_file"], "LMC_side.raw.txt");
}

TEST(Recorder, SidecarKeepsEachDevicesModelModeAndOtherSideHands) {
  RecorderConfig rc = test::recorder_config(test::scratch_dir("rec_model_mode"), "modes");
  rc.backend = "leapc";
  Recorder rec(rc);
  rec.start();
  DeviceEvent a;
  a.kind = DeviceEventKind::kAppeared;
  a.info = {"LP22222", "leapc", "Leap Motion Controller 2", ""};
  rec.device_event(a, 2, "LMC2");
  DeviceEvent mode;
  mode.kind = DeviceEventKind::kTrackingMode;
  mode.info.serial = "LP22222";
  mode.info.tracking_mode = "desktop";
  rec.device_event(mode, 2, "LMC2");
  HandFrame f;
  for (auto& p : f.points) p.setZero();
  f.device_id = 2;
  f.hand_present = true;
  for (int k = 0; k < 3; ++k) {
    f.frame_id = k;
    f.timestamp_us = 1000 * k;
    ASSERT_TRUE(rec.offer(f, 1'000'000 + k, false));
  }
  rec.other_side_hand(2, 1'000'001);
  rec.other_side_hand(2, 1'000'002);
  rec.stop({{"LP22222", "LMC2"}});
  const auto j = read_json(rec.paths().sidecar);
  const auto sc = recorder_sidecar_from_json(j, "modes");
  const SidecarDevice* d = sc.device(2);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->frames_written, 3);
  EXPECT_EQ(d->model, "Leap Motion Controller 2");
  EXPECT_EQ(d->tracking_mode, "desktop");
  EXPECT_EQ(d->frames_other_side_hand, 2);
  bool mode_event = false;
  for (const auto& e : j["events"])
    mode_event =
        mode_event || (e["event"] == "tracking_mode" && e["tracking_mode"] == "desktop" && e["slot"] == "LMC2");
  EXPECT_TRUE(mode_event) << j["events"].dump();
}

TEST(ClockAlignment, AClockReadAtTheSnapshotIsCarriedToTheEventOnTheHostClock) {
  HubSnapshot snap;
  snap.host_time_ns = 5'000'000'000;
  DeviceStatus a;
  a.serial = "LP1";
  a.slot = "LMC1";
  a.slot_index = 0;
  a.frames_received = 10;
  a.latest_host_receive_ns = 4'990'000'000;  // arrived 10 ms before the snapshot
  HandFrame fa;
  for (auto& p : fa.points) p.setZero();
  fa.frame_id = 7;
  fa.timestamp_us = 1'000'000;  // captured 35 ms before it arrived: the clock read 1'045'000 at the snapshot
  a.latest = fa;
  a.device_clock_us = 1'045'000;
  snap.devices = {a};
  const auto j = clock_alignment_json(snap, "CaptureStart sent", 5'003'000'000, 9, "");
  const auto& d = j["devices"][0];
  EXPECT_EQ(d["device_clock_method"], "read");
  EXPECT_EQ(d["device_clock_at_event_us"], 1'048'000);      // the read clock + 3 ms
  EXPECT_EQ(d["device_clock_extrapolated_us"], 1'013'000);  // the frame's timestamp + 13 ms: 35 ms early
  EXPECT_EQ(d["latest_frame_latency_us"], 35'000);
  EXPECT_EQ(d["latest_frame_id"], 7);
  EXPECT_TRUE(d["device_clock_uncertainty_us"].is_null()) << "a source that does not say how well it read";
}

}  // namespace recorder_test
}  // namespace lmc::devices
