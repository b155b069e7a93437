// C3D reader/writer: files built byte by byte here (independently of the writer), writer round
// trips in every processor × storage format, and malformed files rejected with a clear message.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>

#include "core/common/error.h"
#include "core/io/c3d.h"
#include "tests/support/reference_data.h"

namespace lmc {
namespace {

// Minimal little-endian byte builder for hand-made Intel files.
struct Bytes {
  std::vector<std::uint8_t> b;
  bool dec = false;  // floats in DEC (VAX F) form: IEEE bits of 4·v, 16-bit words swapped
  void u8(int v) { b.push_back(static_cast<std::uint8_t>(v)); }
  void i16(int v) {
    const auto u = static_cast<std::uint16_t>(static_cast<std::int16_t>(v));
    u8(u & 0xFF);
    u8(u >> 8);
  }
  void f32(float v) {
    if (dec) v *= 4.0f;
    std::uint32_t u;
    std::memcpy(&u, &v, 4);
    if (dec) u = (u << 16) | (u >> 16);
    for (int k = 0; k < 4; ++k) u8(static_cast<int>((u >> (8 * k)) & 0xFF));
  }
  void str(const std::string& s) { b.insert(b.end(), s.begin(), s.end()); }
  void pad_to(size_t n) { b.resize(n, 0); }
};

// Group record: name, id; parameter record with raw data.
void group(Bytes& x, const std::string& name, int id) {
  x.u8(static_cast<int>(name.size()));
  x.u8(-id & 0xFF);
  x.str(name);
  x.i16(3);
  x.u8(0);
}
void param(Bytes& x, const std::string& name, int gid, int type, std::vector<int> dims,
           const std::vector<std::uint8_t>& data) {
  x.u8(static_cast<int>(name.size()));
  x.u8(gid);
  x.str(name);
  x.i16(static_cast<int>(2 + 1 + 1 + dims.size() + data.size() + 1));
  x.u8(type & 0xFF);
  x.u8(static_cast<int>(dims.size()));
  for (int d : dims) x.u8(d);
  x.b.insert(x.b.end(), data.begin(), data.end());
  x.u8(0);
}
std::vector<std::uint8_t> le16(int v) {
  Bytes t;
  t.i16(v);
  return t.b;
}
std::vector<std::uint8_t> lef(float v, bool dec = false) {
  Bytes t;
  t.dec = dec;
  t.f32(v);
  return t.b;
}

// Intel, integer storage (scale 0.5), 2 points, 3 frames, 2 analog samples per frame to skip;
// point B missing in frame 2 (negative residual). Header POINT count deliberately disagrees (9):
// the parameters are the master.
std::vector<std::uint8_t> hand_made_int_file(bool dec = false) {
  Bytes x;
  x.dec = dec;
  x.u8(2);
  x.u8(0x50);
  x.i16(9);  // points (wrong on purpose)
  x.i16(2);  // analog samples per frame
  x.i16(1);  // first frame
  x.i16(3);  // last frame
  x.i16(0);  // max gap
  x.f32(0.5f);
  x.i16(3);  // data start block
  x.i16(2);  // analog per channel
  x.f32(100.0f);
  x.pad_to(512);
  x.u8(1);
  x.u8(0x50);
  x.u8(1);              // one parameter block
  x.u8(dec ? 85 : 84);  // DEC or Intel (both store integers little-endian)
  group(x, "POINT", 1);
  param(x, "USED", 1, 2, {}, le16(2));
  param(x, "SCALE", 1, 4, {}, lef(0.5f, dec));
  param(x, "RATE", 1, 4, {}, lef(100.0f, dec));
  param(x, "DATA_START", 1, 2, {}, le16(3));
  param(x, "FRAMES", 1, 2, {}, le16(3));
  param(x, "UNITS", 1, -1, {2}, {'m', 'm'});
  param(x, "LABELS", 1, -1, {4, 2}, {'A', ' ', ' ', ' ', 'S', ':', 'B', '\0'});
  group(x, "ANALOG", 2);
  param(x, "USED", 2, 2, {}, le16(1));
  param(x, "RATE", 2, 4, {}, lef(200.0f, dec));
  x.u8(0);
  x.u8(0);
  x.pad_to(1024);
  for (int f = 0; f < 3; ++f) {
    // A = (f, 2f, -f) mm → integers / 0.5
    x.i16(2 * f);
    x.i16(4 * f);
    x.i16(-2 * f);
    x.i16(0);
    if (f == 1) {
      x.i16(0);
      x.i16(0);
      x.i16(0);
      x.i16(-1);
    } else {
      x.i16(20);
      x.i16(40);
      x.i16(60);
      x.i16(0x0102);
    }
    x.i16(1234);  // analog
    x.i16(-1234);
  }
  x.pad_to(1536);
  return x.b;
}

TEST(C3d, ReadsHandMadeIntelIntegerFile) {
  const C3dData d = parse_c3d(hand_made_int_file(), "hand.c3d");
  EXPECT_EQ(d.processor, C3dProcessor::kIntel);
  EXPECT_FALSE(d.float_storage);
  ASSERT_EQ(d.point_count(), 2);
  EXPECT_EQ(d.labels[0], "A");
  EXPECT_EQ(d.labels[1], "S:B");
  EXPECT_EQ(d.analog_per_frame, 2);
  EXPECT_DOUBLE_EQ(d.point_rate_hz, 100.0);
  ASSERT_EQ(d.frame_count(), 3);
  EXPECT_DOUBLE_EQ(d.positions[2][0].x(), 2.0);
  EXPECT_DOUBLE_EQ(d.positions[2][0].y(), 4.0);
  EXPECT_DOUBLE_EQ(d.positions[2][0].z(), -2.0);
  EXPECT_DOUBLE_EQ(d.positions[0][1].z(), 30.0);
  EXPECT_TRUE(std::isnan(d.positions[1][1].x()));
  EXPECT_DOUBLE_EQ(d.positions[2][1].y(), 20.0);
  // The mapping's "Subject:" prefix rule finds "B" in "S:B".
  const MarkerSeries m = d.to_marker_series("hand.c3d");
  EXPECT_EQ(m.names[1], "S:B");
}

// The same file as a DEC (VAX) machine writes it: only the floats (scale, rates) differ.
TEST(C3d, ReadsHandMadeDecIntegerFile) {
  const auto bytes = hand_made_int_file(true);
  EXPECT_EQ(bytes[512 + 3], 85);
  const C3dData d = parse_c3d(bytes, "dec.c3d");
  EXPECT_EQ(d.processor, C3dProcessor::kDec);
  EXPECT_FALSE(d.float_storage);
  EXPECT_DOUBLE_EQ(d.point_rate_hz, 100.0);
  ASSERT_EQ(d.frame_count(), 3);
  EXPECT_DOUBLE_EQ(d.positions[2][0].y(), 4.0);  // 8 × scale 0.5
  EXPECT_DOUBLE_EQ(d.positions[0][1].z(), 30.0);
  EXPECT_TRUE(std::isnan(d.positions[1][1].x()));
}

TEST(C3d, ReadsHandMadeFloatFileInMetres) {
  Bytes x;
  x.u8(2);
  x.u8(0x50);
  x.i16(1);
  x.i16(0);
  x.i16(1);
  x.i16(2);
  x.i16(0);
  x.f32(-0.01f);
  x.i16(3);
  x.i16(0);
  x.f32(50.0f);
  x.pad_to(512);
  x.u8(1);
  x.u8(0x50);
  x.u8(1);
  x.u8(84);
  group(x, "POINT", 3);
  param(x, "USED", 3, 2, {}, le16(1));
  param(x, "SCALE", 3, 4, {}, lef(-0.01f));
  param(x, "RATE", 3, 4, {}, lef(50.0f));
  param(x, "UNITS", 3, -1, {1}, {'m'});
  param(x, "LABELS", 3, -1, {3, 1}, {'T', 'i', 'p'});
  x.u8(0);
  x.u8(0);
  x.pad_to(1024);
  x.f32(0.1f);
  x.f32(0.2f);
  x.f32(0.3f);
  x.f32(0.0f);
  x.f32(1.0f);
  x.f32(2.0f);
  x.f32(3.0f);
  x.f32(-1.0f);
  x.pad_to(1536);
  const C3dData d = parse_c3d(x.b, "float.c3d");
  EXPECT_TRUE(d.float_storage);
  ASSERT_EQ(d.frame_count(), 2);  // from the header: no POINT:FRAMES here
  EXPECT_EQ(d.units, "m");
  const MarkerSeries m = d.to_marker_series("float.c3d");
  EXPECT_NEAR(m.positions[0][0].x(), 100.0, 1e-4);
  EXPECT_NEAR(m.positions[0][0].z(), 300.0, 1e-4);
  EXPECT_TRUE(std::isnan(m.positions[1][0].y()));
  EXPECT_DOUBLE_EQ(m.rate_hz, 50.0);
}

C3dData sample_data(int points, int frames) {
  C3dData d;
  d.point_rate_hz = 100.0;
  for (int p = 0; p < points; ++p) d.labels.push_back("M" + std::to_string(p));
  for (int f = 0; f < frames; ++f) {
    std::vector<Eigen::Vector3d> row;
    for (int p = 0; p < points; ++p) row.emplace_back(0.5 * f + p, -12.25 + p, 300.0 - 0.25 * f);
    d.positions.push_back(row);
  }
  d.positions[1][0] = Eigen::Vector3d::Constant(std::nan(""));
  return d;
}

class C3dRoundTrip : public ::testing::TestWithParam<std::tuple<C3dProcessor, bool>> {};

TEST_P(C3dRoundTrip, WriterOutputReadsBackExactly) {
  const auto [proc, floats] = GetParam();
  const C3dData in = sample_data(3, 5);
  C3dWriteOptions o;
  o.processor = proc;
  o.float_storage = floats;
  o.int_scale = 0.25;
  const auto bytes = write_c3d_bytes(in, o);
  EXPECT_EQ(bytes.size() % 512, 0u);
  const C3dData out = parse_c3d(bytes, "rt.c3d");
  EXPECT_EQ(out.processor, proc);
  EXPECT_EQ(out.float_storage, floats);
  ASSERT_EQ(out.labels, in.labels);
  ASSERT_EQ(out.frame_count(), 5);
  for (int f = 0; f < 5; ++f) {
    for (int p = 0; p < 3; ++p) {
      const auto& a = in.positions[static_cast<size_t>(f)][static_cast<size_t>(p)];
      const auto& b = out.positions[static_cast<size_t>(f)][static_cast<size_t>(p)];
      if (std::isnan(a.x())) {
        EXPECT_TRUE(std::isnan(b.x()));
      } else {
        EXPECT_NEAR((a - b).norm(), 0.0, 1e-9) << "frame " << f << " point " << p;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllFormats, C3dRoundTrip,
                         ::testing::Combine(::testing::Values(C3dProcessor::kIntel, C3dProcessor::kDec,
                                                              C3dProcessor::kMips),
                                            ::testing::Bool()));

TEST(C3d, ManyPointsUseLabels2) {
  const C3dData in = sample_data(300, 2);
  const C3dData out = parse_c3d(write_c3d_bytes(in), "many.c3d");
  ASSERT_EQ(out.point_count(), 300);
  EXPECT_EQ(out.labels[299], "M299");
  EXPECT_NEAR(out.positions[0][299].x(), 299.0, 1e-9);
}

TEST(C3d, DecFloatEncodingMatchesKnownBytes) {
  // 1.0 in VAX F format is the 16-bit words 0x4080, 0x0000 stored little-endian: 80 40 00 00.
  C3dData d;
  d.labels = {"X"};
  d.positions = {{Eigen::Vector3d(1.0, 0.0, -2.0)}};
  C3dWriteOptions o;
  o.processor = C3dProcessor::kDec;
  const auto bytes = write_c3d_bytes(d, o);
  const C3dData back = parse_c3d(bytes, "dec.c3d");
  const size_t data_at = (bytes.size() / 512 - 1) * 512;
  EXPECT_EQ(bytes[data_at + 0], 0x80);
  EXPECT_EQ(bytes[data_at + 1], 0x40);
  EXPECT_EQ(bytes[data_at + 2], 0x00);
  EXPECT_EQ(bytes[data_at + 3], 0x00);
  EXPECT_DOUBLE_EQ(back.positions[0][0].z(), -2.0);
}

void expect_error(const std::vector<std::uint8_t>& bytes, const std::string& fragment) {
  try {
    parse_c3d(bytes, "bad.c3d");
    FAIL() << "expected an error containing '" << fragment << "'";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(fragment), std::string::npos) << what;
    EXPECT_NE(what.find("bad.c3d"), std::string::npos) << what;
  }
}

TEST(C3d, RejectsMalformedFiles) {
  expect_error({}, "too short");
  std::vector<std::uint8_t> not_c3d(512, 0);
  not_c3d[0] = 2;
  expect_error(not_c3d, "not a C3D file");
  auto past = hand_made_int_file();
  past[0] = 40;  // parameter block past the end
  expect_error(past, "past the end");
  auto proc = hand_made_int_file();
  proc[512 + 3] = 90;
  expect_error(proc, "unknown processor type 90");
  auto truncated = hand_made_int_file();
  truncated.resize(1024 + 10);  // data section cut inside frame 1
  expect_error(truncated, "data section ends after 0 of 3 frames");
  auto bad_offset = hand_made_int_file();
  bad_offset[512 + 4 + 2 + 5] = 0xF0;  // POINT group's offset → far past the section
  bad_offset[512 + 4 + 2 + 6] = 0x7F;
  EXPECT_THROW(parse_c3d(bad_offset, "bad.c3d"), Error);
}

// A 1 KB file with zero points whose POINT:FRAMES (float) claims 10^8 frames made the
// reader allocate gigabytes; huge analog counts overflowed int. Both are now refused by size.
std::vector<std::uint8_t> hostile_file(int points, float frames, float analog_rate) {
  Bytes x;
  x.u8(2);
  x.u8(0x50);
  x.i16(points);
  x.i16(0);
  x.i16(1);
  x.i16(1);
  x.i16(0);
  x.f32(-1.0f);
  x.i16(3);
  x.i16(0);
  x.f32(100.0f);
  x.pad_to(512);
  x.u8(1);
  x.u8(0x50);
  x.u8(1);
  x.u8(84);
  group(x, "POINT", 1);
  param(x, "USED", 1, 2, {}, le16(points));
  param(x, "SCALE", 1, 4, {}, lef(-1.0f));
  param(x, "RATE", 1, 4, {}, lef(100.0f));
  param(x, "DATA_START", 1, 2, {}, le16(3));
  param(x, "FRAMES", 1, 4, {}, lef(frames));
  group(x, "ANALOG", 2);
  param(x, "USED", 2, 2, {}, le16(analog_rate > 0.0f ? 60000 : 0));
  param(x, "RATE", 2, 4, {}, lef(analog_rate > 0.0f ? analog_rate : 100.0f));
  x.u8(0);
  x.u8(0);
  x.pad_to(1024);
  return x.b;
}

TEST(C3d, RejectsFrameCountsTheFileCannotHold) {
  const auto no_points = hostile_file(0, 1e8f, 0.0f);
  ASSERT_EQ(no_points.size(), 1024u);
  expect_error(no_points, "implausible frame count");
  expect_error(hostile_file(0, 1e30f, 0.0f), "implausible frame count");
  expect_error(hostile_file(0, -5.0f, 0.0f), "implausible frame count");
  // With points, frames × points × bytes per point must fit in the data section.
  expect_error(hostile_file(1, 1e8f, 0.0f), "data section ends after 0 of 100000000 frames");
  // A few empty frames in a small file are harmless and still read.
  const C3dData few = parse_c3d(hostile_file(0, 3.0f, 0.0f), "few.c3d");
  EXPECT_EQ(few.frame_count(), 3);
}

TEST(C3d, RejectsAnalogCountsThatWouldOverflow) {
  // 60000 channels × (3e38 Hz / 100 Hz) samples per frame: far beyond int and the file.
  expect_error(hostile_file(1, 1.0f, 3e38f), "more analog samples per frame than the file has bytes");
  expect_error(hostile_file(1, 1.0f, 1e9f), "implausible");
}

TEST(C3d, SaveAndReadFile) {
  const auto dir = test::scratch_dir("c3d_save");
  const C3dData in = sample_data(2, 3);
  save_c3d(dir / "t.c3d", in);
  const C3dData out = read_c3d(dir / "t.c3d");
  EXPECT_EQ(out.labels, in.labels);
  EXPECT_NEAR(out.positions[2][1].z(), 299.5, 1e-9);
  EXPECT_THROW(read_c3d(dir / "missing.c3d"), Error);
}

}  // namespace
}  // namespace lmc
