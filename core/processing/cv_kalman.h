#pragma once
// The one-coordinate constant-velocity Kalman step of the default fusion (white-noise
// acceleration with spectral density `accel_psd`, state = position and velocity, symmetric 2×2
// covariance). Shared by the offline forward pass (fusion_smoother.cpp) and the online fuser
// (online_fusion.cpp) so the two use the same model, arithmetic for arithmetic.
namespace lmc {

struct CvKalman {
  double x0 = 0, x1 = 0;             // position, velocity
  double p00 = 0, p01 = 0, p11 = 0;  // covariance

  // Starts at a first measurement z with variance r, at rest; the velocity spread is wide
  // ((100 mm/s)²) so the first few updates find the real velocity.
  void start(double z, double r) {
    start_state(z, x0, x1);
    p00 = r;
    p01 = 0.0;
    p11 = 1.0e4;
  }

  // x ← F x, P ← F P Fᵀ + Q(dt) with the discrete white-noise-acceleration Q.
  void predict(double dt, double accel_psd) {
    predict_state(dt, x0, x1);
    predict_covariance(dt, accel_psd);
  }

  // Position measurement z with variance r.
  void update(double z, double r) {
    const Gain g = update_covariance(r);
    update_state(g, z, x0, x1);
  }

  // The two halves of each step. The covariance and the gain depend only on the measurement
  // variances, not on the values: lanes measured with the same variances at the same steps (the
  // x, y and z of one point) share them, and only their states need stepping each
  // (fusion_smoother.cpp). predict and update are exactly these halves.
  struct Gain {
    double k0 = 0, k1 = 0;
  };
  static void start_state(double z, double& x0, double& x1) {
    x0 = z;
    x1 = 0.0;
  }
  static void predict_state(double dt, double& x0, double x1) { x0 += dt * x1; }
  void predict_covariance(double dt, double accel_psd) {
    const double q00 = accel_psd * dt * dt * dt / 3.0, q01 = accel_psd * dt * dt / 2.0, q11 = accel_psd * dt;
    const double n00 = p00 + 2.0 * dt * p01 + dt * dt * p11 + q00;
    const double n01 = p01 + dt * p11 + q01;
    const double n11 = p11 + q11;
    p00 = n00;
    p01 = n01;
    p11 = n11;
  }
  Gain update_covariance(double r) {
    const double sv = p00 + r;
    const Gain g{p00 / sv, p01 / sv};
    const double m00 = (1.0 - g.k0) * p00, m01 = (1.0 - g.k0) * p01, m11 = p11 - g.k1 * p01;
    p00 = m00;
    p01 = m01;
    p11 = m11;
    return g;
  }
  static void update_state(Gain g, double z, double& x0, double& x1) {
    const double inn = z - x0;
    x0 += g.k0 * inn;
    x1 += g.k1 * inn;
  }
};

}  // namespace lmc
