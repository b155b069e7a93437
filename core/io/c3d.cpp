#include "core/io/c3d.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>

#include "core/common/error.h"
#include "core/io/atomic_write.h"

namespace lmc {
namespace {

constexpr size_t kBlock = 512;
constexpr std::uint8_t kC3dKey = 0x50;  // the second byte of every C3D file

// Byte-order aware access to the file's numbers.
class Codec {
 public:
  explicit Codec(C3dProcessor p) : p_(p) {}

  std::int16_t i16(const std::uint8_t* b) const {
    const auto u = p_ == C3dProcessor::kMips ? static_cast<std::uint16_t>((b[0] << 8) | b[1])
                                             : static_cast<std::uint16_t>(b[0] | (b[1] << 8));
    return static_cast<std::int16_t>(u);
  }
  std::uint16_t u16(const std::uint8_t* b) const { return static_cast<std::uint16_t>(i16(b)); }
  float f32(const std::uint8_t* b) const {
    std::uint32_t bits = 0;
    switch (p_) {
      case C3dProcessor::kIntel:
        bits = static_cast<std::uint32_t>(b[0]) | (static_cast<std::uint32_t>(b[1]) << 8) |
               (static_cast<std::uint32_t>(b[2]) << 16) | (static_cast<std::uint32_t>(b[3]) << 24);
        return std::bit_cast<float>(bits);
      case C3dProcessor::kMips:
        bits = (static_cast<std::uint32_t>(b[0]) << 24) | (static_cast<std::uint32_t>(b[1]) << 16) |
               (static_cast<std::uint32_t>(b[2]) << 8) | static_cast<std::uint32_t>(b[3]);
        return std::bit_cast<float>(bits);
      case C3dProcessor::kDec: {
        // VAX F: the two 16-bit halves are swapped relative to IEEE and the exponent bias differs
        // by two (docs/formats.md): swap, read as IEEE, divide by 4; a zero exponent is zero.
        const std::uint32_t hi = static_cast<std::uint32_t>(b[0]) | (static_cast<std::uint32_t>(b[1]) << 8);
        const std::uint32_t lo = static_cast<std::uint32_t>(b[2]) | (static_cast<std::uint32_t>(b[3]) << 8);
        bits = (hi << 16) | lo;
        if ((bits & 0x7F800000u) == 0) return 0.0f;
        return std::bit_cast<float>(bits) / 4.0f;
      }
    }
    return 0.0f;
  }

  void put_i16(std::vector<std::uint8_t>& out, std::int16_t v) const {
    const auto u = static_cast<std::uint16_t>(v);
    if (p_ == C3dProcessor::kMips) {
      out.push_back(static_cast<std::uint8_t>(u >> 8));
      out.push_back(static_cast<std::uint8_t>(u & 0xFF));
    } else {
      out.push_back(static_cast<std::uint8_t>(u & 0xFF));
      out.push_back(static_cast<std::uint8_t>(u >> 8));
    }
  }
  void put_f32(std::vector<std::uint8_t>& out, float v) const {
    std::uint32_t bits = 0;
    switch (p_) {
      case C3dProcessor::kIntel:
        bits = std::bit_cast<std::uint32_t>(v);
        for (int k = 0; k < 4; ++k) out.push_back(static_cast<std::uint8_t>(bits >> (8 * k)));
        return;
      case C3dProcessor::kMips:
        bits = std::bit_cast<std::uint32_t>(v);
        for (int k = 3; k >= 0; --k) out.push_back(static_cast<std::uint8_t>(bits >> (8 * k)));
        return;
      case C3dProcessor::kDec: {
        bits = v == 0.0f ? 0u : std::bit_cast<std::uint32_t>(v * 4.0f);
        const std::uint32_t hi = bits >> 16, lo = bits & 0xFFFFu;
        out.push_back(static_cast<std::uint8_t>(hi & 0xFF));
        out.push_back(static_cast<std::uint8_t>(hi >> 8));
        out.push_back(static_cast<std::uint8_t>(lo & 0xFF));
        out.push_back(static_cast<std::uint8_t>(lo >> 8));
        return;
      }
    }
  }

 private:
  C3dProcessor p_;
};

struct Param {
  int type = 0;  // −1 char, 1 byte, 2 int16, 4 float
  std::vector<int> dims;
  const std::uint8_t* data = nullptr;
  size_t size = 0;
  size_t offset = 0;  // file offset of the data, for messages
};

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::string trim(const std::string& s) {
  size_t b = 0, e = s.size();
  while (b < e && (s[b] == ' ' || s[b] == '\0')) ++b;
  while (e > b && (s[e - 1] == ' ' || s[e - 1] == '\0')) --e;
  return s.substr(b, e - b);
}

class Reader {
 public:
  Reader(const std::vector<std::uint8_t>& bytes, std::string source) : b_(bytes), source_(std::move(source)) {}

  [[noreturn]] void fail(size_t offset, const std::string& what) const {
    throw Error(ErrorLocation(source_), "C3D byte " + std::to_string(offset) + ": " + what);
  }

  C3dData read() {
    C3dData out;
    const Codec c = read_parameter_section(out);
    const HeaderCopies h = header_copies(c);
    const PointLayout layout = read_point_layout(c, h, out);
    const long frames = read_frame_count(c, h, out);
    out.analog_per_frame = read_analog_per_frame(c, h, out.point_rate_hz);
    read_names(layout.used, out);
    read_points(c, layout, frames, out);
    return out;
  }

 private:
  // The header's copies of the point parameters (words are 1-based in the specification); the
  // parameters win where both exist.
  struct HeaderCopies {
    int points = 0;
    int analog = 0;
    int first = 0;
    int last = 0;
    float scale = 0.0f;
    int data_start = 0;
    float rate = 0.0f;
  };
  HeaderCopies header_copies(const Codec& c) const {
    auto hword = [&](int w) { return c.u16(&b_[static_cast<size_t>(2 * (w - 1))]); };
    return {hword(2), hword(3), hword(4), hword(5), c.f32(&b_[12]), hword(9), c.f32(&b_[20])};
  }

  // What the point data looks like: how many points, their scale (negative: stored as floats) and
  // the block the data starts at.
  struct PointLayout {
    int used = 0;
    double scale = 0.0;
    int data_start = 0;
  };

  // The header block's key, then the parameter section: its processor type (the byte order of
  // every number) and its records.
  Codec read_parameter_section(C3dData& out) {
    if (b_.size() < kBlock)
      fail(0, "file is " + std::to_string(b_.size()) + " bytes, too short for a C3D header (512)");
    if (b_[1] != kC3dKey) fail(1, "not a C3D file (second byte is " + std::to_string(b_[1]) + ", expected 0x50)");
    const size_t param_block = b_[0];
    if (param_block < 2) fail(0, "parameter section block number " + std::to_string(param_block) + " is invalid");
    const size_t pstart = (param_block - 1) * kBlock;
    if (pstart + 4 > b_.size())
      fail(0, "parameter section (block " + std::to_string(param_block) + ") lies past the end of the file");
    const int proc = b_[pstart + 3];
    if (proc < 84 || proc > 86) {
      fail(pstart + 3, "unknown processor type " + std::to_string(proc) + " (expected 84 Intel, 85 DEC or 86 MIPS)");
    }
    out.processor = static_cast<C3dProcessor>(proc);
    const Codec c(out.processor);
    const size_t nblocks = b_[pstart + 2];
    size_t pend = pstart + std::max<size_t>(nblocks, 1) * kBlock;
    if (pend > b_.size()) {
      out.warnings.push_back("parameter section claims " + std::to_string(nblocks) +
                             " blocks but the file ends sooner");
      pend = b_.size();
    }
    parse_parameters(c, pstart + 4, pend, out);
    return c;
  }

  // POINT:USED, SCALE, RATE, DATA_START and UNITS, each from the header where the parameter is missing.
  PointLayout read_point_layout(const Codec& c, const HeaderCopies& h, C3dData& out) const {
    PointLayout layout;
    layout.used =
        has("POINT", "USED") ? static_cast<int>(static_cast<std::uint16_t>(integer("POINT", "USED", c))) : h.points;
    layout.scale = has("POINT", "SCALE") ? number("POINT", "SCALE", c) : h.scale;
    if (layout.scale == 0.0 || !std::isfinite(layout.scale)) fail(12, "POINT:SCALE is zero or not a number");
    out.point_scale = layout.scale;
    out.float_storage = layout.scale < 0.0;
    out.point_rate_hz = has("POINT", "RATE") ? number("POINT", "RATE", c) : h.rate;
    if (!(out.point_rate_hz > 0.0) || !std::isfinite(out.point_rate_hz)) {
      out.point_rate_hz = h.rate;
      if (!(out.point_rate_hz > 0.0)) fail(20, "point rate is not positive");
    }
    layout.data_start = has("POINT", "DATA_START") ? static_cast<std::uint16_t>(integer("POINT", "DATA_START", c)) : 0;
    if (layout.data_start <= 0) layout.data_start = h.data_start;
    if (layout.data_start < 2) fail(16, "DATA_START block " + std::to_string(layout.data_start) + " is invalid");
    if (has("POINT", "UNITS")) {
      const auto u = strings("POINT", "UNITS");
      if (!u.empty()) out.units = trim(u.front());
    }
    return layout;
  }

  // Frames: TRIAL:ACTUAL_START/END_FIELD (two words each) for long trials, else POINT:FRAMES, else header.
  long read_frame_count(const Codec& c, const HeaderCopies& h, C3dData& out) const {
    long frames = static_cast<long>(h.last) - h.first + 1;
    out.first_frame = h.first;
    if (has("POINT", "FRAMES")) {
      const Param& p = get("POINT", "FRAMES");
      if (p.type == 4) {
        // A float count (used past 65535 frames) can say anything; beyond 2^32 it is no count.
        const double v = number("POINT", "FRAMES", c);
        if (!std::isfinite(v) || v < 0.0 || v > 4294967295.0) {
          fail(p.offset, "POINT:FRAMES is " + std::to_string(v) + "; implausible frame count");
        }
        frames = static_cast<long>(std::lround(v));
      } else {
        frames = static_cast<long>(static_cast<std::uint16_t>(integer("POINT", "FRAMES", c)));
      }
    }
    if (has("TRIAL", "ACTUAL_START_FIELD") && has("TRIAL", "ACTUAL_END_FIELD")) {
      const auto s = words("TRIAL", "ACTUAL_START_FIELD", c), e = words("TRIAL", "ACTUAL_END_FIELD", c);
      if (s.size() >= 2 && e.size() >= 2) {
        const long first = s[0] + 65536L * s[1], last = e[0] + 65536L * e[1];
        if (last >= first) frames = last - first + 1;
      }
    }
    return frames < 0 ? 0 : frames;
  }

  // Analog samples to skip after each point frame.
  int read_analog_per_frame(const Codec& c, const HeaderCopies& h, double point_rate_hz) const {
    int analog = h.analog;
    if (has("ANALOG", "USED")) {
      const int channels = static_cast<std::uint16_t>(integer("ANALOG", "USED", c));
      double arate = has("ANALOG", "RATE") ? number("ANALOG", "RATE", c) : 0.0;
      if (channels == 0) {
        analog = 0;
      } else if (arate > 0.0) {
        // In floating point first: a hostile ANALOG:RATE / POINT:RATE ratio overflows int (and
        // lround) long before it is compared with anything. Every sample takes at least two bytes,
        // so more samples per frame than the file has bytes cannot be real.
        const double per_frame = static_cast<double>(channels) * std::round(arate / point_rate_hz);
        if (!std::isfinite(per_frame) || per_frame > static_cast<double>(b_.size())) {
          fail(0, "ANALOG:USED (" + std::to_string(channels) + ") x ANALOG:RATE (" + std::to_string(arate) +
                      ") / POINT:RATE (" + std::to_string(point_rate_hz) +
                      ") claims more analog samples per frame than the file has bytes (" + std::to_string(b_.size()) +
                      "); implausible");
        }
        analog = static_cast<int>(per_frame);
      }
    }
    return analog;
  }

  // The points' labels and descriptions, the manufacturer's texts and the parameters' names.
  void read_names(int used, C3dData& out) const {
    // Labels: LABELS, then LABELS2, LABELS3 … for more than 255 points.
    std::vector<std::string> labels;
    for (int k = 1; static_cast<int>(labels.size()) < used; ++k) {
      const std::string name = k == 1 ? "LABELS" : "LABELS" + std::to_string(k);
      if (!has("POINT", name)) break;
      for (const auto& s : strings("POINT", name)) labels.push_back(trim(s));
    }
    if (static_cast<int>(labels.size()) < used) {
      out.warnings.push_back("POINT:LABELS names " + std::to_string(labels.size()) + " of " + std::to_string(used) +
                             " points; the rest are called Point<n>");
      for (int k = static_cast<int>(labels.size()); k < used; ++k) labels.push_back("Point" + std::to_string(k + 1));
    }
    labels.resize(static_cast<size_t>(used));
    out.labels = labels;
    // Descriptions like labels (DESCRIPTIONS, DESCRIPTIONS2 …); optional, so never an error.
    for (int k = 1; static_cast<int>(out.descriptions.size()) < used; ++k) {
      const std::string name = k == 1 ? "DESCRIPTIONS" : "DESCRIPTIONS" + std::to_string(k);
      if (!has("POINT", name) || get("POINT", name).type != -1) break;
      for (const auto& s : strings("POINT", name)) out.descriptions.push_back(trim(s));
    }
    if (!out.descriptions.empty()) out.descriptions.resize(static_cast<size_t>(used));
    auto text_of = [&](const char* name) {
      if (!has("MANUFACTURER", name) || get("MANUFACTURER", name).type != -1) return std::string();
      std::string joined;
      for (const auto& s : strings("MANUFACTURER", name)) joined += (joined.empty() ? "" : " ") + trim(s);
      return joined;
    };
    out.manufacturer_company = text_of("COMPANY");
    out.manufacturer_software = text_of("SOFTWARE");
    out.manufacturer_version = text_of("VERSION_LABEL");
    out.parameter_names = parameter_order_;
  }

  // The data section: `frames` frames of `used` points (X, Y, Z, residual each) and the analog
  // samples after them, which are skipped.
  void read_points(const Codec& c, const PointLayout& layout, long frames, C3dData& out) const {
    const int used = layout.used;
    const int analog = out.analog_per_frame;
    const size_t word = out.float_storage ? 4 : 2;
    const size_t frame_bytes = (static_cast<size_t>(used) * 4 + static_cast<size_t>(std::max(analog, 0))) * word;
    const size_t dstart = static_cast<size_t>(layout.data_start - 1) * kBlock;
    if (dstart > b_.size())
      fail(16, "data section (block " + std::to_string(layout.data_start) + ") lies past the end of the file");
    if (frame_bytes == 0 && frames > 0 && static_cast<size_t>(frames) > b_.size()) {
      // Frames without points or analog samples take no bytes, so the file's size cannot bound
      // them; a claim of more frames than the file has bytes is a corrupt or hostile count (each
      // frame would still cost memory to hold).
      fail(0, "claims " + std::to_string(frames) + " frames but has no points or analog samples, and only " +
                  std::to_string(b_.size()) + " bytes; implausible frame count");
    }
    if (frame_bytes > 0) {
      const long available = static_cast<long>((b_.size() - dstart) / frame_bytes);
      if (available < frames) {
        fail(dstart + static_cast<size_t>(available) * frame_bytes,
             "data section ends after " + std::to_string(available) + " of " + std::to_string(frames) + " frames");
      }
    }
    const double abs_scale = std::abs(layout.scale);
    out.positions.assign(static_cast<size_t>(frames), std::vector<Eigen::Vector3d>(static_cast<size_t>(used)));
    for (long f = 0; f < frames; ++f) {
      const std::uint8_t* fp = &b_[dstart + static_cast<size_t>(f) * frame_bytes];
      for (int p = 0; p < used; ++p) {
        out.positions[static_cast<size_t>(f)][static_cast<size_t>(p)] =
            read_point(c, fp + static_cast<size_t>(p) * 4 * word, out.float_storage, abs_scale);
      }
    }
  }

  // One point's X, Y, Z at `q`; NaN when its residual says it is missing or it is not finite.
  static Eigen::Vector3d read_point(const Codec& c, const std::uint8_t* q, bool float_storage, double abs_scale) {
    Eigen::Vector3d v;
    double residual = 0.0;
    if (float_storage) {
      v = {c.f32(q), c.f32(q + 4), c.f32(q + 8)};
      const float r = c.f32(q + 12);
      // The fourth word of a float file is an integer stored as a float (docs/formats.md).
      residual = std::isfinite(r)
                     ? static_cast<double>(static_cast<std::int16_t>(std::lround(std::clamp(r, -32768.0f, 32767.0f))))
                     : -1.0;
    } else {
      v = {c.i16(q) * abs_scale, c.i16(q + 2) * abs_scale, c.i16(q + 4) * abs_scale};
      residual = c.i16(q + 6);
    }
    if (residual < 0.0 || !std::isfinite(v.x()) || !std::isfinite(v.y()) || !std::isfinite(v.z())) {
      v = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
    }
    return v;
  }

  void parse_parameters(const Codec& c, size_t pos, size_t end, C3dData& out) {
    std::map<int, std::string> group_names;
    struct Pending {
      int group;
      std::string name;
      Param p;
    };
    std::vector<Pending> pending;
    while (pos + 2 <= end) {
      const auto name_len = static_cast<int>(std::abs(static_cast<std::int8_t>(b_[pos])));
      const auto id = static_cast<int>(static_cast<std::int8_t>(b_[pos + 1]));
      if (name_len == 0 || id == 0) break;
      const size_t name_at = pos + 2;
      if (name_at + static_cast<size_t>(name_len) + 2 > end)
        fail(pos, "parameter record runs past the parameter section");
      const std::string name =
          upper(std::string(reinterpret_cast<const char*>(&b_[name_at]), static_cast<size_t>(name_len)));
      const size_t off_at = name_at + static_cast<size_t>(name_len);
      const int next = c.i16(&b_[off_at]);
      const size_t body = off_at + 2;
      if (id < 0) {
        group_names[-id] = name;
      } else {
        if (body + 2 > end) fail(body, "parameter " + name + " is truncated");
        Param p;
        p.type = static_cast<std::int8_t>(b_[body]);
        const int nd = b_[body + 1];
        if (p.type != -1 && p.type != 1 && p.type != 2 && p.type != 4) {
          fail(body, "parameter " + name + " has unknown element type " + std::to_string(p.type));
        }
        if (nd > 7) fail(body + 1, "parameter " + name + " has " + std::to_string(nd) + " dimensions (at most 7)");
        if (body + 2 + static_cast<size_t>(nd) > end) fail(body, "parameter " + name + " is truncated");
        size_t count = 1;
        for (int k = 0; k < nd; ++k) {
          p.dims.push_back(b_[body + 2 + static_cast<size_t>(k)]);
          count *= static_cast<size_t>(p.dims.back());
        }
        p.size = count * static_cast<size_t>(std::abs(p.type));
        p.offset = body + 2 + static_cast<size_t>(nd);
        if (p.offset + p.size > end) fail(p.offset, "parameter " + name + "'s data runs past the parameter section");
        p.data = &b_[p.offset];
        pending.push_back({id, name, p});
      }
      if (next == 0) break;
      if (next < 0) fail(off_at, "record " + name + " has a negative offset to the next record");
      pos = off_at + static_cast<size_t>(next);
      if (pos > end) {
        // Seen in the wild (docs/formats.md): keep what was read when it is enough, else reject.
        bool have_points = false;
        for (const auto& pd : pending) have_points = have_points || pd.name == "USED";
        if (!have_points) fail(off_at, "record " + name + "'s offset points past the parameter section");
        out.warnings.push_back("parameter record " + name +
                               " points past the parameter section; later records ignored");
        break;
      }
    }
    for (auto& [g, n, p] : pending) {
      const auto it = group_names.find(g);
      const std::string group = it != group_names.end() ? it->second : "#" + std::to_string(g);
      params_[group + ":" + n] = p;
      parameter_order_.push_back(group + ":" + n);
    }
  }

  bool has(const std::string& g, const std::string& n) const { return params_.count(g + ":" + n) != 0; }
  const Param& get(const std::string& g, const std::string& n) const { return params_.at(g + ":" + n); }

  int integer(const std::string& g, const std::string& n, const Codec& c) const {
    const Param& p = get(g, n);
    if (p.size < static_cast<size_t>(std::abs(p.type)) || p.size == 0) fail(p.offset, g + ":" + n + " is empty");
    switch (p.type) {
      case 1:
        return p.data[0];
      case 2:
        return c.i16(p.data);
      case 4:
        return static_cast<int>(std::lround(c.f32(p.data)));
      default:
        fail(p.offset, g + ":" + n + " is text, expected a number");
    }
  }
  double number(const std::string& g, const std::string& n, const Codec& c) const {
    const Param& p = get(g, n);
    if (p.type == 4 && p.size >= 4) return c.f32(p.data);
    return integer(g, n, c);
  }
  std::vector<long> words(const std::string& g, const std::string& n, const Codec& c) const {
    const Param& p = get(g, n);
    std::vector<long> out;
    if (p.type != 2) return out;
    for (size_t k = 0; k + 1 < p.size; k += 2) out.push_back(c.u16(p.data + k));
    return out;
  }
  std::vector<std::string> strings(const std::string& g, const std::string& n) const {
    const Param& p = get(g, n);
    if (p.type != -1) fail(p.offset, g + ":" + n + " is not text");
    std::vector<std::string> out;
    if (p.dims.empty()) {
      out.emplace_back(reinterpret_cast<const char*>(p.data), p.size);
      return out;
    }
    const auto len = static_cast<size_t>(p.dims[0]);
    if (len == 0) return out;
    for (size_t k = 0; k + len <= p.size; k += len) out.emplace_back(reinterpret_cast<const char*>(p.data + k), len);
    return out;
  }

  const std::vector<std::uint8_t>& b_;
  std::string source_;
  std::map<std::string, Param> params_;
  std::vector<std::string> parameter_order_;
};

// ---- writer ----

struct ParamOut {
  std::string name;
  int type;
  std::vector<int> dims;
  std::vector<std::uint8_t> data;
};

void put_record_group(std::vector<std::uint8_t>& out, const Codec& c, const std::string& name, int id) {
  out.push_back(static_cast<std::uint8_t>(name.size()));
  out.push_back(static_cast<std::uint8_t>(static_cast<std::int8_t>(-id)));
  out.insert(out.end(), name.begin(), name.end());
  c.put_i16(out, 3);  // offset field (2) + description length (1)
  out.push_back(0);
}

void put_record_param(std::vector<std::uint8_t>& out, const Codec& c, const ParamOut& p, int group) {
  out.push_back(static_cast<std::uint8_t>(p.name.size()));
  out.push_back(static_cast<std::uint8_t>(group));
  out.insert(out.end(), p.name.begin(), p.name.end());
  const size_t next = 2 + 1 + 1 + p.dims.size() + p.data.size() + 1;
  // The offset to the next record is a signed 16-bit word.
  if (next > 32767)
    throw Error("C3D writer: parameter " + p.name + " holds " + std::to_string(p.data.size()) +
                " bytes, too many for one record");
  c.put_i16(out, static_cast<std::int16_t>(next));
  out.push_back(static_cast<std::uint8_t>(static_cast<std::int8_t>(p.type)));
  out.push_back(static_cast<std::uint8_t>(p.dims.size()));
  for (int d : p.dims) out.push_back(static_cast<std::uint8_t>(d));
  out.insert(out.end(), p.data.begin(), p.data.end());
  out.push_back(0);
}

ParamOut int_param(const Codec& c, const std::string& name, int v) {
  ParamOut p{name, 2, {}, {}};
  c.put_i16(p.data, static_cast<std::int16_t>(static_cast<std::uint16_t>(v)));
  return p;
}
ParamOut float_param(const Codec& c, const std::string& name, float v) {
  ParamOut p{name, 4, {}, {}};
  c.put_f32(p.data, v);
  return p;
}
ParamOut text_param(const std::string& name, const std::vector<std::string>& items, bool force_2d) {
  size_t len = 1;
  for (const auto& s : items) len = std::max(len, s.size());
  if (len > 255) throw Error("C3D writer: label '" + items.front().substr(0, 20) + "…' is longer than 255 characters");
  ParamOut p{name, -1, {}, {}};
  if (items.size() == 1 && !force_2d) {
    p.dims = {static_cast<int>(len)};
  } else {
    p.dims = {static_cast<int>(len), static_cast<int>(items.size())};
  }
  for (const auto& s : items) {
    std::string padded = s;
    padded.resize(len, ' ');
    p.data.insert(p.data.end(), padded.begin(), padded.end());
  }
  return p;
}

// The writer's four parameter groups. POINT:DATA_START (kC3dDataStartParam) is written as 0 and
// patched once the section's size says where the data begins.
struct C3dParamGroups {
  std::vector<ParamOut> point, analog, trial, manufacturer;
};
constexpr size_t kC3dDataStartParam = 3;

std::vector<ParamOut> c3d_point_params(const Codec& c, const C3dData& data, float scale) {
  const int points = data.point_count();
  std::vector<ParamOut> point_params;
  point_params.push_back(int_param(c, "USED", points));
  point_params.push_back(float_param(c, "SCALE", scale));
  point_params.push_back(float_param(c, "RATE", static_cast<float>(data.point_rate_hz)));
  point_params.push_back(int_param(c, "DATA_START", 0));
  point_params.push_back(int_param(c, "FRAMES", data.frame_count()));
  point_params.push_back(text_param("UNITS", {data.units.empty() ? std::string("mm") : data.units}, false));
  for (int k = 0; k * 255 < std::max(points, 1); ++k) {
    const auto b = data.labels.begin() + std::min(points, k * 255);
    const auto e = data.labels.begin() + std::min(points, (k + 1) * 255);
    std::vector<std::string> chunk(b, e);
    if (chunk.empty()) chunk.emplace_back("");
    point_params.push_back(text_param(k == 0 ? "LABELS" : "LABELS" + std::to_string(k + 1), chunk, true));
    if (points == 0) break;
  }
  if (!data.descriptions.empty()) {
    // One description per point, in 255-point chunks like the labels.
    std::vector<std::string> all = data.descriptions;
    all.resize(static_cast<size_t>(points));
    for (int k = 0; k * 255 < points; ++k) {
      std::vector<std::string> chunk(all.begin() + k * 255, all.begin() + std::min(points, (k + 1) * 255));
      point_params.push_back(text_param(k == 0 ? "DESCRIPTIONS" : "DESCRIPTIONS" + std::to_string(k + 1), chunk, true));
    }
  }
  return point_params;
}

ParamOut c3d_two_word_param(const Codec& c, const std::string& name, long v) {
  ParamOut p{name, 2, {2}, {}};
  c.put_i16(p.data, static_cast<std::int16_t>(static_cast<std::uint16_t>(v & 0xFFFF)));
  c.put_i16(p.data, static_cast<std::int16_t>(static_cast<std::uint16_t>((v >> 16) & 0xFFFF)));
  return p;
}

// TRIAL: the frame range as two 16-bit words each (low, high), so readers that take the range
// from here rather than from the header's 16-bit fields see the same frames. None without frames.
std::vector<ParamOut> c3d_trial_params(const Codec& c, const C3dData& data) {
  const int frames = data.frame_count();
  if (frames <= 0) return {};
  const long first = std::max(data.first_frame, 1);
  const long last = first + std::max(frames, 1) - 1;
  return {c3d_two_word_param(c, "ACTUAL_START_FIELD", first), c3d_two_word_param(c, "ACTUAL_END_FIELD", last),
          float_param(c, "CAMERA_RATE", static_cast<float>(data.point_rate_hz))};
}

std::vector<ParamOut> c3d_manufacturer_params(const C3dData& data) {
  std::vector<ParamOut> manufacturer_params;
  if (!data.manufacturer_company.empty())
    manufacturer_params.push_back(text_param("COMPANY", {data.manufacturer_company}, false));
  if (!data.manufacturer_software.empty())
    manufacturer_params.push_back(text_param("SOFTWARE", {data.manufacturer_software}, false));
  if (!data.manufacturer_version.empty())
    manufacturer_params.push_back(text_param("VERSION_LABEL", {data.manufacturer_version}, false));
  return manufacturer_params;
}

// The parameter records with DATA_START set; an empty TRIAL or MANUFACTURER group is left out.
std::vector<std::uint8_t> c3d_parameter_records(const Codec& c, C3dParamGroups& groups, int data_start) {
  groups.point[kC3dDataStartParam] = int_param(c, "DATA_START", data_start);
  std::vector<std::uint8_t> s;
  put_record_group(s, c, "POINT", 1);
  for (const auto& p : groups.point) put_record_param(s, c, p, 1);
  put_record_group(s, c, "ANALOG", 2);
  for (const auto& p : groups.analog) put_record_param(s, c, p, 2);
  if (!groups.trial.empty()) {
    put_record_group(s, c, "TRIAL", 3);
    for (const auto& p : groups.trial) put_record_param(s, c, p, 3);
  }
  if (!groups.manufacturer.empty()) {
    put_record_group(s, c, "MANUFACTURER", 4);
    for (const auto& p : groups.manufacturer) put_record_param(s, c, p, 4);
  }
  s.push_back(0);  // a zero name length ends the list
  s.push_back(0);
  return s;
}

std::vector<std::uint8_t> c3d_header_block(const Codec& c, const C3dData& data, float scale, int data_start) {
  const int points = data.point_count();
  const int frames = data.frame_count();
  std::vector<std::uint8_t> header;
  header.push_back(2);
  header.push_back(kC3dKey);
  c.put_i16(header, static_cast<std::int16_t>(static_cast<std::uint16_t>(points)));
  c.put_i16(header, 0);  // analog samples per frame
  c.put_i16(header, static_cast<std::int16_t>(static_cast<std::uint16_t>(std::max(data.first_frame, 1))));
  c.put_i16(header, static_cast<std::int16_t>(
                        static_cast<std::uint16_t>(std::max(data.first_frame, 1) + std::max(frames, 1) - 1)));
  c.put_i16(header, 0);  // max interpolation gap
  c.put_f32(header, scale);
  c.put_i16(header, static_cast<std::int16_t>(data_start));
  c.put_i16(header, 0);  // analog samples per channel
  c.put_f32(header, static_cast<float>(data.point_rate_hz));
  header.resize(kBlock, 0);
  return header;
}

// Every frame's points (x, y, z, residual), as floats or as integers at the scale.
void append_c3d_frames(std::vector<std::uint8_t>& out, const Codec& c, const C3dData& data,
                       const C3dWriteOptions& options) {
  const int points = data.point_count();
  const int frames = data.frame_count();
  for (int f = 0; f < frames; ++f) {
    for (int p = 0; p < points; ++p) {
      const Eigen::Vector3d& v = data.positions[static_cast<size_t>(f)][static_cast<size_t>(p)];
      const bool missing = !(std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()));
      if (options.float_storage) {
        for (int k = 0; k < 3; ++k) c.put_f32(out, missing ? 0.0f : static_cast<float>(v[k]));
        c.put_f32(out, missing ? -1.0f : 0.0f);
      } else {
        for (int k = 0; k < 3; ++k) {
          const double q = missing ? 0.0 : std::round(v[k] / options.int_scale);
          if (q < -32768.0 || q > 32767.0) {
            throw Error("C3D writer: point " + data.labels[static_cast<size_t>(p)] + " frame " + std::to_string(f + 1) +
                        " does not fit integer storage at scale " + std::to_string(options.int_scale));
          }
          c.put_i16(out, static_cast<std::int16_t>(q));
        }
        c.put_i16(out, missing ? -1 : 0);
      }
    }
  }
}

}  // namespace

MarkerSeries C3dData::to_marker_series(const std::string& source) const {
  double factor = 1.0;
  const std::string u = upper(units);
  if (u == "M") {
    factor = 1000.0;
  } else if (u == "CM") {
    factor = 10.0;
  } else if (u != "MM" && !u.empty()) {
    throw Error(ErrorLocation(source), "C3D POINT:UNITS is '" + units + "' (expected mm, cm or m)");
  }
  MarkerSeries m;
  m.names = labels;
  m.rate_hz = point_rate_hz;
  m.source = source;
  m.positions = positions;
  if (factor != 1.0) {
    for (auto& row : m.positions) {
      for (auto& p : row) p *= factor;
    }
  }
  return m;
}

C3dData parse_c3d(const std::vector<std::uint8_t>& bytes, const std::string& source) {
  return Reader(bytes, source).read();
}

C3dData read_c3d(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(ErrorLocation(path.string()), "cannot open C3D file");
  // The header block first: a file that is not a C3D (a 2 GB file of garbage) is refused by the
  // parser's own signature check on that block alone, before the rest is read.
  std::vector<std::uint8_t> bytes(kBlock);
  in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(kBlock));
  bytes.resize(static_cast<size_t>(in.gcount()));
  if (bytes.size() < kBlock || bytes[1] != kC3dKey) return parse_c3d(bytes, path.string());
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (!ec) bytes.reserve(static_cast<size_t>(size));
  std::vector<char> chunk(1 << 16);
  while (in.read(chunk.data(), static_cast<std::streamsize>(chunk.size())) || in.gcount() > 0)
    bytes.insert(bytes.end(), chunk.begin(), chunk.begin() + in.gcount());
  return parse_c3d(bytes, path.string());
}

std::vector<std::uint8_t> write_c3d_bytes(const C3dData& data, const C3dWriteOptions& options) {
  const Codec c(options.processor);
  const int points = data.point_count();
  const int frames = data.frame_count();
  if (frames > 65535) throw Error("C3D writer: more than 65535 frames are not supported");
  if (points > 65535) throw Error("C3D writer: too many points");
  const float scale = options.float_storage ? -1.0f : static_cast<float>(options.int_scale);
  if (!options.float_storage && !(options.int_scale > 0.0)) throw Error("C3D writer: integer scale must be positive");

  // Parameter section (built first: DATA_START depends on its size).
  C3dParamGroups groups{c3d_point_params(c, data, scale),
                        {int_param(c, "USED", 0), float_param(c, "RATE", static_cast<float>(data.point_rate_hz))},
                        c3d_trial_params(c, data),
                        c3d_manufacturer_params(data)};
  std::vector<std::uint8_t> records = c3d_parameter_records(c, groups, 0);
  const size_t pblocks = (records.size() + 4 + kBlock - 1) / kBlock;
  if (pblocks > 255)
    throw Error("C3D writer: the parameter section needs " + std::to_string(pblocks) + " blocks (at most 255)");
  const int data_start = static_cast<int>(2 + pblocks);
  records = c3d_parameter_records(c, groups, data_start);

  std::vector<std::uint8_t> out;
  out.reserve(kBlock * (1 + pblocks) + static_cast<size_t>(frames) * static_cast<size_t>(points) * 16 + kBlock);
  const std::vector<std::uint8_t> header = c3d_header_block(c, data, scale, data_start);
  out.insert(out.end(), header.begin(), header.end());
  // Parameter blocks.
  out.push_back(1);
  out.push_back(kC3dKey);
  out.push_back(static_cast<std::uint8_t>(pblocks));
  out.push_back(static_cast<std::uint8_t>(options.processor));
  out.insert(out.end(), records.begin(), records.end());
  out.resize(kBlock * (1 + pblocks), 0);
  append_c3d_frames(out, c, data, options);
  out.resize((out.size() + kBlock - 1) / kBlock * kBlock, 0);
  return out;
}

void save_c3d(const std::filesystem::path& path, const C3dData& data, const C3dWriteOptions& options) {
  const auto bytes = write_c3d_bytes(data, options);
  write_file_atomically(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

}  // namespace lmc
