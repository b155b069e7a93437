// The soak's parts (devices/soak/): the rig of any size, the count kept at the source, the fusion
// in groups, the process statistics, and two short soaks in real time: one that loses nothing and
// one whose disk fills, which must be reported as lost frames, a failed trial and a failing
// verdict.
#include <fcntl.h>
#include <unistd.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <regex>
#include <thread>

#include "core/io/layout_json.h"
#include "devices/soak/counting_source.h"
#include "devices/soak/grouped_fusion.h"
#include "devices/soak/process_stats.h"
#include "devices/soak/soak_engine.h"
#include "tests/support/full_disk_sink.h"
#include "tests/support/reference_data.h"

namespace lmc::devices {
namespace soak_test {  // named: test files share unity batches

using ::testing::HasSubstr;

TEST(SoakLayout, RepeatsTheInitialLayoutForAnyNumberOfControllers) {
  const Layout base = load_layout_or_preset("paper-initial");
  const Layout l = soak_layout(12);
  ASSERT_EQ(l.device_count(), 12);
  EXPECT_EQ(l.devices[0].slot, "LMC1");
  EXPECT_EQ(l.devices[11].slot, "LMC12");
  EXPECT_EQ(l.devices[5].pose, base.devices[1].pose);
  EXPECT_EQ(l.devices[11].pose, base.devices[3].pose);
  EXPECT_FALSE(l.devices[4].serial.has_value());
}

// A source that delivers frames only when the test says so.
class ManualSource final : public FrameSource {
 public:
  std::string backend_name() const override { return "manual"; }
  void start(FrameSink& sink) override { sink_ = &sink; }
  void stop() override {}
  void frame(std::int64_t host_ns) {
    SourceFrame f;
    f.serial = "M-1";
    f.host_receive_ns = host_ns;
    sink_->on_frame(f);
  }

 private:
  FrameSink* sink_ = nullptr;
};

class CollectingSink final : public FrameSink {
 public:
  void on_device_event(const DeviceEvent&) override {}
  void on_frame(const SourceFrame& f) override { times.push_back(f.host_receive_ns); }
  std::vector<std::int64_t> times;
};

TEST(CountingSource, PassesEveryFrameOnAndKeepsItsTimeUntilTaken) {
  auto inner = std::make_unique<ManualSource>();
  ManualSource* manual = inner.get();
  CountingSource counting(std::move(inner));
  CollectingSink sink;
  counting.start(sink);
  manual->frame(10);
  manual->frame(20);
  EXPECT_THAT(counting.take_frame_times(), ::testing::ElementsAre(10, 20));
  manual->frame(30);
  EXPECT_THAT(counting.take_frame_times(), ::testing::ElementsAre(30));
  EXPECT_TRUE(counting.take_frame_times().empty());
  EXPECT_EQ(counting.frames_produced(), 3);
  EXPECT_THAT(sink.times, ::testing::ElementsAre(10, 20, 30));
  EXPECT_EQ(counting.backend_name(), "manual");
}

TEST(GroupedFusion, ARigLargerThanALayoutIsFusedInGroupsOfEight) {
  const Layout l = soak_layout(12);
  GroupedFusion fusion(l);
  EXPECT_EQ(fusion.groups(), 2);
  HandFrame f;
  f.hand_present = false;
  f.timestamp_us = 1000;
  for (const int id : {1, 8, 9, 12}) {
    f.device_id = id;
    fusion.tap(f);
  }
  f.device_id = 13;  // beyond the rig: ignored, not refused by a group
  fusion.tap(f);
  for (int i = 0; i < 400 && fusion.stats().frames_fused < 4; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  fusion.stop();
  const LiveFusionStats s = fusion.stats();
  EXPECT_EQ(s.frames_tapped, 4);
  EXPECT_EQ(s.frames_fused, 4);
  EXPECT_EQ(s.frames_refused, 0);  // slots 9 and 12 arrived as slots 1 and 4 of the second group
  EXPECT_EQ(layout_slice(l, 8, 4).devices[0].slot, "LMC9");
}

TEST(ProcessStats, CountsAnOpenedFile) {
  const ProcessStats before = read_process_stats();
  EXPECT_GT(before.rss_mb, 0);
  EXPECT_GE(before.threads, 1);
  const int fd = ::open("/proc/self/statm", O_RDONLY | O_CLOEXEC);
  ASSERT_GE(fd, 0);
  const ProcessStats during = read_process_stats();
  ::close(fd);
  EXPECT_EQ(during.fds, before.fds + 1);
  EXPECT_EQ(read_process_stats().fds, before.fds);
}

SoakConfig short_soak(const std::string& name) {
  SoakConfig c;
  // Two trials at least, with room for a loaded machine: a trial's checks (file read back, verdict,
  // under the sanitizers) can take over a second, and a trial starts only with a second left.
  c.seconds = 4.0;
  c.devices = 2;
  c.rate_hz = 60;
  c.trial_seconds = 1.0;
  c.output_dir = test::scratch_dir(name);
  c.background = false;  // its pose set takes a while under the sanitizers; the ctest soak runs it
  c.progress_every_s = 0;
  return c;
}

TEST(Soak, AShortSessionLosesNothingAndEveryFrameProducedIsARow) {
  const SoakReport r = run_soak(short_soak("soak_short"));
  EXPECT_TRUE(r.ok()) << ::testing::PrintToString(r.problems);
  ASSERT_GE(r.trials.size(), 2u);
  for (const SoakTrial& t : r.trials) {
    EXPECT_EQ(t.status, "completed") << t.name;
    EXPECT_GT(t.produced, 0) << t.name;
    EXPECT_EQ(t.written, t.produced) << t.name;
    EXPECT_EQ(t.lost(), 0) << t.name;
    EXPECT_FALSE(t.verdict.empty()) << t.name;
  }
  EXPECT_EQ(r.lost, 0);
  EXPECT_EQ(r.written, r.produced);
  EXPECT_GT(r.fusion.frames_tapped, 0);
  EXPECT_FALSE(r.samples.empty());
  // Files are removed once checked.
  EXPECT_TRUE(std::filesystem::is_empty(r.config.output_dir));
  const std::string line = soak_summary_line(r);
  EXPECT_TRUE(std::regex_match(line, std::regex("soak: [0-9]+ frames from 2 controllers in [0-9]+ s, 0 lost, "
                                                "heap [0-9]+→[0-9]+ MB, RSS [0-9]+→[0-9]+ MB, fds [0-9]+→[0-9]+")))
      << line;
  EXPECT_EQ(soak_report_to_json(r).at("lost"), 0);
}

// The growth test judges what the program holds, so memory held as a leak holds it must fail it,
// whatever the allocator does with resident pages.
TEST(Soak, MemoryHeldAfterEveryTrialIsReportedAsGrowth) {
  SoakConfig c = short_soak("soak_deliberate_leak");
  c.leak_mb_per_trial = 16;
  const SoakReport r = run_soak(c);
  ASSERT_GE(r.trials.size(), 2u);
  EXPECT_EQ(r.lost, 0);
  EXPECT_FALSE(r.ok());
  ASSERT_EQ(r.problems.size(), 1u) << ::testing::PrintToString(r.problems);
  EXPECT_THAT(r.problems.front(), HasSubstr("memory held by the program (heap in use) grew"));
  EXPECT_GE(r.heap_floor_end_mb - r.heap_floor_baseline_mb, 16.0 * static_cast<double>(r.trials.size() - 2));
  EXPECT_GT(r.end.heap_in_use_mb, r.baseline.heap_in_use_mb + 15.0);
}

// Fails like a full disk after `limit` bytes of one file.
using test::FullDiskSink;

TEST(Soak, AWriterThatFailsIsReportedAsLostFramesAFailedTrialAndAFailingVerdict) {
  SoakConfig c = short_soak("soak_full_disk");
  c.open_sink = [](const std::filesystem::path& p) {
    return std::make_unique<FullDiskSink>(open_file_sink(p), 16 * 1024);
  };
  const SoakReport r = run_soak(c);
  EXPECT_FALSE(r.ok());
  ASSERT_FALSE(r.trials.empty());
  const SoakTrial& t = r.trials.front();
  EXPECT_EQ(t.status, "failed");
  EXPECT_GT(t.lost(), 0);
  EXPECT_EQ(t.lost(), t.queue_dropped + t.writer_lost);
  EXPECT_EQ(t.verdict, "fail");
  EXPECT_THAT(t.reasons.front(), HasSubstr("No space left on device"));
  ASSERT_FALSE(r.problems.empty());
  EXPECT_THAT(r.problems.front(), HasSubstr("trial soak_0001: "));
  EXPECT_THAT(r.problems.front(), HasSubstr("frames lost"));
  EXPECT_THAT(r.problems.front(), HasSubstr("its sidecar says failed"));
  EXPECT_GT(r.lost, 0);
  EXPECT_THAT(soak_summary_line(r), HasSubstr(" " + std::to_string(r.lost) + " lost"));
}

TEST(Soak, AFileCutMidLineIsAFailedTrialAndTheSoakGoesOn) {
  SoakConfig c = short_soak("soak_cut_file");
  // So little room that every trial's file ends inside a row the reader cannot take.
  c.open_sink = [](const std::filesystem::path& p) { return std::make_unique<FullDiskSink>(open_file_sink(p), 3000); };
  const SoakReport r = run_soak(c);
  EXPECT_FALSE(r.ok());
  ASSERT_GE(r.trials.size(), 2u) << "the soak stopped at the first unreadable file";
  for (const SoakTrial& t : r.trials) {
    EXPECT_EQ(t.verdict, "fail") << t.name;
    ASSERT_FALSE(t.reasons.empty()) << t.name;
    EXPECT_THAT(t.reasons.front(), HasSubstr("No space left on device")) << t.name;
  }
}

}  // namespace soak_test
}  // namespace lmc::devices
