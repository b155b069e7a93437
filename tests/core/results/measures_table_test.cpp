// The per-frame measures table (measures.tsv) is built a row at a time with the quick fixed-point
// writer; every number must read as append_fixed writes it, including the ones only the general
// path takes, and a Vicon recording shorter than the LMC one leaves "nan" cells.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "core/common/number_format.h"
#include "core/processing/trial_pipeline.h"
#include "core/results/trial_outputs.h"

namespace lmc {
namespace {

FrameMeasures measures_from(double first, double step) {
  FrameMeasures m;
  double v = first;
  for (double& x : m.segment_mm) x = (v += step);
  for (double& x : m.finger_mm) x = (v += step);
  for (double& x : m.angle_deg) x = (v += step);
  return m;
}

// The row as the rule writes it: append_fixed for each number, in the table's column order.
void expected_values(std::string& o, const FrameMeasures& m) {
  for (double v : m.segment_mm) append_fixed(o += '\t', v, 4);
  for (double v : m.finger_mm) append_fixed(o += '\t', v, 4);
  for (double v : m.angle_deg) append_fixed(o += '\t', v, 4);
}

TEST(MeasuresTable, RowsReadAsAppendFixedWritesEveryNumber) {
  TrialAnalysis r;
  r.lmc_frames = {measures_from(12.34567, 1.000049), measures_from(-0.00004, -3.3), measures_from(0.0, 0.0)};
  // Values the quick writer leaves to the general path (1e300), and NaN, ±inf, −0.
  r.lmc_frames[2].segment_mm[0] = 1e300;
  r.lmc_frames[2].segment_mm[1] = std::numeric_limits<double>::quiet_NaN();
  r.lmc_frames[2].segment_mm[2] = -std::numeric_limits<double>::infinity();
  r.lmc_frames[2].segment_mm[3] = -0.0;
  r.lmc_frames[2].angle_deg[5] = 1234567890123456.7;  // over 2^63 units of 1e-4: general path
  r.has_vicon = true;
  r.vicon_frames = {measures_from(40.0, 0.25)};  // shorter than the LMC frames
  DeviceTrack d1, d3;
  d1.device_id = 1;
  d3.device_id = 3;
  r.device_frame.devices = {d1, d3};
  r.labels = {{FingerLabels{1, 0, 1, -1, 1}, FingerLabels{0, 0, 0, 0, 0}, FingerLabels{-1, -1, -1, -1, -1}},
              {FingerLabels{1, 1, 1, 1, 1}, FingerLabels{1, 0, 0, 1, 0}, FingerLabels{0, 1, 0, 1, 0}}};

  const std::string table = format_measures_tsv(r);
  const size_t header_end = table.find('\n');
  ASSERT_NE(header_end, std::string::npos);
  EXPECT_NE(table.find("\tvis_LMC3_"), std::string::npos);

  std::string expected;
  for (size_t f = 0; f < r.lmc_frames.size(); ++f) {
    expected += std::to_string(f);
    append_fixed(expected += '\t', static_cast<double>(f) * 0.01, 2);
    expected_values(expected, r.lmc_frames[f]);
    if (f < r.vicon_frames.size()) {
      expected_values(expected, r.vicon_frames[f]);
    } else {
      for (int k = 0; k < kNumSegments + kNumFingers + kNumAngles; ++k) expected += "\tnan";
    }
    for (const auto& device : r.labels) {
      for (const auto label : device[f]) expected += '\t' + std::to_string(label);
    }
    expected += '\n';
  }
  EXPECT_EQ(table.substr(header_end + 1), expected);
  // The general path's numbers are whole in the table.
  EXPECT_NE(table.find("\t" + format_fixed(1e300, 4) + "\tnan\t-inf\t-0.0000\t"), std::string::npos);
  EXPECT_NE(table.find("\t" + format_fixed(1234567890123456.7, 4) + "\t"), std::string::npos);
}

TEST(MeasuresTable, QuickWriterDeclinesOnlyWhatAppendFixedWritesTheLongWay) {
  char room[kFixedQuickRoom];
  EXPECT_EQ(std::string(room, write_fixed(room, -2.5, 4)), "-2.5000");
  EXPECT_EQ(std::string(room, write_fixed(room, 0.00005, 4)), "0.0001");  // above half: the binary value
  EXPECT_EQ(std::string(room, write_fixed(room, std::nan(""), 4)), "nan");
  EXPECT_EQ(write_fixed(room, 1e300, 4), nullptr);
  EXPECT_EQ(write_fixed(room, 1.5, 10), nullptr);
}

}  // namespace
}  // namespace lmc
