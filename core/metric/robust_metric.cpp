#include "core/metric/robust_metric.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/common/error.h"
#include "core/metric/placement_metric.h"

namespace lmc {
namespace {

using FootprintQuad = std::array<Eigen::Vector2d, 4>;

FootprintQuad footprint_of(const LayoutDevice& d) {
  const Eigen::Matrix3d r = d.pose.rotation();
  const Eigen::Vector3d t = d.pose.translation() + d.offset_mm;
  // The case of the device's own model (LayoutDevice::footprint_mm: width along x, depth along z).
  const double hx = 0.5 * d.footprint_mm.x(), hz = 0.5 * d.footprint_mm.y();
  const std::array<Eigen::Vector3d, 4> corners = {Eigen::Vector3d(-hx, 0, -hz), Eigen::Vector3d(hx, 0, -hz),
                                                  Eigen::Vector3d(hx, 0, hz), Eigen::Vector3d(-hx, 0, hz)};
  FootprintQuad q;
  for (size_t i = 0; i < 4; ++i) {
    const Eigen::Vector3d w = r * corners[i] + t;
    q[i] = {w.x(), w.z()};
  }
  return q;
}

// Separating-axis test of two convex quadrilaterals: they overlap unless some edge normal of
// either separates their projections (touching counts as apart).
bool footprint_quads_overlap(const FootprintQuad& a, const FootprintQuad& b) {
  for (const FootprintQuad* q : {&a, &b}) {
    for (size_t i = 0; i < 4; ++i) {
      const Eigen::Vector2d e = (*q)[(i + 1) % 4] - (*q)[i];
      const Eigen::Vector2d n(-e.y(), e.x());
      if (n.squaredNorm() == 0.0) continue;  // a degenerate edge (a controller on its side)
      double amin = std::numeric_limits<double>::infinity(), amax = -amin, bmin = amin, bmax = -amin;
      for (const auto& p : a) {
        amin = std::min(amin, n.dot(p));
        amax = std::max(amax, n.dot(p));
      }
      for (const auto& p : b) {
        bmin = std::min(bmin, n.dot(p));
        bmax = std::max(bmax, n.dot(p));
      }
      if (amax <= bmin || bmax <= amin) return false;
    }
  }
  return true;
}

double share(std::int64_t part, std::int64_t whole) {
  return whole > 0 ? static_cast<double>(part) / static_cast<double>(whole) : 0.0;
}

}  // namespace

const char* placement_metric_name(PlacementMetricKind kind) {
  return kind == PlacementMetricKind::kStudy ? "study" : "robust";
}

PlacementMetricKind placement_metric_from_name(const std::string& name, const std::string& what) {
  if (name == "study") return PlacementMetricKind::kStudy;
  if (name == "robust") return PlacementMetricKind::kRobust;
  throw Error(what + ": unknown metric \"" + name + "\" (study or robust)");
}

std::array<Eigen::Vector2d, 4> controller_footprint(const LayoutDevice& d) {
  return footprint_of(d);
}

bool footprints_overlap(const LayoutDevice& a, const LayoutDevice& b) {
  return footprint_quads_overlap(footprint_of(a), footprint_of(b));
}

double footprint_overlap_share(const Layout& layout) {
  const size_t n = layout.devices.size();
  if (n < 2) return 0.0;
  std::int64_t overlapping = 0, pairs = 0;
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = i + 1; j < n; ++j) {
      ++pairs;
      if (footprints_overlap(layout.devices[i], layout.devices[j])) ++overlapping;
    }
  }
  return share(overlapping, pairs);
}

RobustTerms robust_terms(const LayoutTally& t, double footprint_share, const RobustWeights& w) {
  RobustTerms r;
  r.metric_m = placement_metric(t.c);
  std::int64_t redundant = 0;
  for (size_t i = 2; i < t.c.size(); ++i) redundant += t.c[i];
  r.redundancy = t.frames > 0 ? 1.0 - share(redundant, t.frames) : 0.0;
  if (t.devices > 0 && t.frames > 0 && w.participation_floor > 0) {
    double shortfall = 0;
    for (const auto seeing : t.device_seeing_frames) {
      shortfall += std::max(0.0, w.participation_floor - share(seeing, t.frames)) / w.participation_floor;
    }
    r.participation = shortfall / t.devices;
  }
  r.axis_cut = share(t.cut_pairs(), t.seeing_pairs());
  r.centring = t.seeing_pairs() > 0
                   ? static_cast<double>(t.off_centre_sum()) / kOffCentreScale / static_cast<double>(t.seeing_pairs())
                   : 1.0;  // nobody sees the hand: as badly centred as it gets
  r.footprint = footprint_share;
  r.metric_m_inside_cut = placement_metric(t.c_inside_cut);
  // M_cut is added last, so that with its weight 0 every total is bit for bit what it was before
  // the term existed (x + 0 = x).
  r.total = r.metric_m + w.redundancy * r.redundancy + w.participation * r.participation + w.axis_cut * r.axis_cut +
            w.centring * r.centring + w.footprint * r.footprint + w.inside_cut * r.metric_m_inside_cut;
  return r;
}

std::span<const RobustTermInfo> robust_term_infos() {
  static constexpr RobustTermInfo kTerms[] = {
      {"M", "M", "the study's metric", nullptr, &RobustTerms::metric_m},
      {"redundancy", "redundancy", "share of frames with a finger seen by fewer than 2 controllers",
       &RobustWeights::redundancy, &RobustTerms::redundancy},
      {"participation", "participation", "controllers' shortfall below seeing a finger in 20 % of frames",
       &RobustWeights::participation, &RobustTerms::participation},
      {"axis_cut", "axis cut", "share of seeing controller-frames with a seen marker beyond 250 mm",
       &RobustWeights::axis_cut, &RobustTerms::axis_cut},
      {"centring", "centring", "mean off-centre of the palm in the seeing pyramids (0 axis, 1 edge)",
       &RobustWeights::centring, &RobustTerms::centring},
      {"footprint", "footprint", "share of controller pairs whose footprints overlap", &RobustWeights::footprint,
       &RobustTerms::footprint},
      {"inside_cut", "M inside cut", "M with a finger beyond a controller's 250 mm cut unseen by it",
       &RobustWeights::inside_cut, &RobustTerms::metric_m_inside_cut},
  };
  return kTerms;
}

double robust_term_weight(const RobustWeights& w, const RobustTermInfo& term) {
  return term.weight != nullptr ? w.*(term.weight) : 1.0;
}

}  // namespace lmc
