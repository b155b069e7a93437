// The pre-flight's stream probe on a source that has streamed everything before the caller runs
// again: a simulated trial played faster than real time, whose thread may finish its two seconds
// while the thread that started it is still descheduled (a busy machine; often under Wine).
#include <gtest/gtest.h>

#include "devices/device_hub.h"
#include "devices/session_runner/stream_probe.h"

namespace lmc::devices {
namespace stream_probe_test {

// Delivers every frame of `seconds` at 120 Hz from inside start(), on the caller's thread: the
// extreme of a source whose thread outruns the one that started it.
class EagerSource final : public FrameSource {
 public:
  explicit EagerSource(double seconds) : frames_(static_cast<int>(seconds * 120)) {}
  std::string backend_name() const override { return "eager"; }
  bool realtime() const override { return false; }
  bool finished() const override { return finished_; }
  void stop() override {}
  void start(FrameSink& sink) override {
    DeviceEvent appeared;
    appeared.kind = DeviceEventKind::kAppeared;
    appeared.info = {"EAGER-1", "eager", "simulated", ""};
    sink.on_device_event(appeared);
    for (int i = 0; i < frames_; ++i) {
      SourceFrame f;
      f.serial = "EAGER-1";
      f.frame.frame_id = i;
      f.frame.timestamp_us = 1'000'000 + i * 1'000'000 / 120;
      f.host_receive_ns = f.frame.timestamp_us * 1000;
      sink.on_frame(f);
    }
    finished_ = true;
  }

 private:
  int frames_;
  bool finished_ = false;
};

Layout one_slot() {
  Layout l;
  l.name = "one";
  LayoutDevice d;
  d.slot = "LMC1";
  l.devices.push_back(d);
  return l;
}

// The probe is attached before the hub starts, so it sees the source's frames however early they
// come; started the other way round, it saw none and the pre-flight said "no controller streams".
TEST(StreamProbe, ASourceThatFinishesAtOnceIsSeenWhenTheProbeStartsTheHub) {
  HubOptions fast;
  fast.backpressure = true;  // simulated time, as `lmc session run --fast` plays it
  DeviceHub hub(one_slot(), fast);
  hub.add_source(std::make_unique<EagerSource>(2.0));
  const std::vector<SlotProbe> slots = probe_streams(hub, std::chrono::milliseconds(2000), 20);
  EXPECT_TRUE(hub.running());
  ASSERT_EQ(slots.size(), 1u);
  EXPECT_EQ(slots[0].slot, "LMC1");
  EXPECT_EQ(slots[0].serial, "EAGER-1");
  EXPECT_EQ(slots[0].frames, 240);
  EXPECT_NEAR(slots[0].rate_hz, 120.0, 0.1);
  hub.stop();
}

// A hub that already runs (the block's hub of real controllers) is probed as it is.
TEST(StreamProbe, ARunningHubIsProbedWithoutARestart) {
  DeviceHub hub(one_slot());
  hub.add_source(std::make_unique<EagerSource>(1.0));
  hub.start();
  const std::vector<SlotProbe> slots = probe_streams(hub, std::chrono::milliseconds(200), 20);
  ASSERT_EQ(slots.size(), 1u);
  EXPECT_EQ(slots[0].serial, "EAGER-1");  // the hub knows the device
  EXPECT_EQ(slots[0].frames, 0);          // whose frames all came before the probe listened
  hub.stop();
}

}  // namespace stream_probe_test
}  // namespace lmc::devices
