#pragma once
// The direction in which a few points spread least: the eigenvector of the smallest eigenvalue of
// their 3 × 3 scatter matrix Σ pᵢpᵢᵀ (points centred). The palm plane's normal
// (core/visibility/frame_prep.h) is one per frame of every device, a quarter of a million per
// subject, so this is built for speed as well as accuracy (least_variance_direction.cpp).
#include <Eigen/Core>

namespace lmc {

// Unit eigenvector of the smallest eigenvalue of the symmetric `scatter`, to within a few units in
// the last place of the exact one wherever that is defined (the two smallest eigenvalues apart).
// Its sign is arbitrary.
Eigen::Vector3d least_variance_direction(const Eigen::Matrix3d& scatter);

}  // namespace lmc
