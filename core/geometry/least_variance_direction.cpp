#include "core/geometry/least_variance_direction.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <optional>

namespace lmc {
namespace {

// The six entries of a symmetric 3 × 3 matrix [[a b c] [b d e] [c e f]].
struct Symmetric3 {
  double a, b, c, d, e, f;
};

// The adjugate of S − μI for a symmetric S (symmetric too): each entry a 2 × 2 cofactor.
struct Adjugate3 {
  double a00, a01, a02, a11, a12, a22;
};
Adjugate3 adjugate(const Symmetric3& s, double mu) {
  const double a = s.a - mu, d = s.d - mu, f = s.f - mu;
  return {d * f - s.e * s.e, s.c * s.e - s.b * f, s.b * s.e - s.c * d,
          a * f - s.c * s.c, s.b * s.c - a * s.e, a * d - s.b * s.b};
}
Eigen::Vector3d times(const Adjugate3& m, const Eigen::Vector3d& n) {
  return {m.a00 * n.x() + m.a01 * n.y() + m.a02 * n.z(), m.a01 * n.x() + m.a11 * n.y() + m.a12 * n.z(),
          m.a02 * n.x() + m.a12 * n.y() + m.a22 * n.z()};
}

// Rayleigh quotient iteration from the adjugate's largest column, or nothing when it does not
// settle quickly on the smallest eigenvalue (then the general solver decides).
//  * adj(S − μI) = Σᵢ Πⱼ≠ᵢ (λⱼ − μ) vᵢvᵢᵀ: for μ near the smallest eigenvalue λ₃ its every column
//    leans towards v₃, by the factor (λ₂ − μ)/(λ₃ − μ) over v₂. With μ = 0 (adj S itself) a palm's
//    columns are within a few per cent of v₃ already.
//  * Each step takes μ = nᵀSn and n ← adj(S − μI) n: the error is cubed (Rayleigh quotient
//    iteration), so two or three steps reach rounding, and no step divides except to normalise.
//  * Accepted when a step no longer turns n (its error was below 1e-7, so the new one is at
//    rounding) and the other two eigenvalues, from the trace and the 2 × 2 minors with μ taken out,
//    are both at least twice μ: the iteration found the smallest one, well apart from the next.
std::optional<Eigen::Vector3d> rayleigh_iteration(const Symmetric3& s) {
  const Adjugate3 adj = adjugate(s, 0.0);
  Eigen::Vector3d n = adj.a00 >= adj.a11 && adj.a00 >= adj.a22 ? Eigen::Vector3d(adj.a00, adj.a01, adj.a02)
                      : adj.a11 >= adj.a22                     ? Eigen::Vector3d(adj.a01, adj.a11, adj.a12)
                                                               : Eigen::Vector3d(adj.a02, adj.a12, adj.a22);
  const double start = n.norm();
  if (!(start > 0.0) || !std::isfinite(start)) return std::nullopt;
  n *= 1.0 / start;
  for (int step = 0; step < 5; ++step) {
    const double mu = s.a * n.x() * n.x() + s.d * n.y() * n.y() + s.f * n.z() * n.z() +
                      2.0 * (s.b * n.x() * n.y() + s.c * n.x() * n.z() + s.e * n.y() * n.z());
    Eigen::Vector3d next = times(adjugate(s, mu), n);
    const double length = next.norm();
    if (!(length > 0.0) || !std::isfinite(length)) return std::nullopt;
    next *= 1.0 / length;
    const double turned = 1.0 - std::abs(next.dot(n));  // ≈ half the squared angle
    n = next;
    if (turned < 1e-14) {
      const double others_sum = s.a + s.d + s.f - mu;
      const double others_product = adj.a00 + adj.a11 + adj.a22 - mu * others_sum;
      const double smaller_other =
          0.5 * (others_sum - std::sqrt(std::max(others_sum * others_sum - 4.0 * others_product, 0.0)));
      if (!(smaller_other >= 2.0 * mu)) return std::nullopt;
      return n;
    }
  }
  return std::nullopt;
}

}  // namespace

Eigen::Vector3d least_variance_direction(const Eigen::Matrix3d& scatter) {
  const Symmetric3 s{scatter(0, 0), scatter(0, 1), scatter(0, 2), scatter(1, 1), scatter(1, 2), scatter(2, 2)};
  if (const auto n = rayleigh_iteration(s)) return *n;
  // Nearly round spreads, points on a line or at one place, non-finite input: Eigen's
  // tridiagonal QR, which is right for every symmetric matrix (eigenvalues sorted increasingly).
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(scatter);
  return eigen.eigenvectors().col(0);
}

}  // namespace lmc
