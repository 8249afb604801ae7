#include "sim/stability/spectrum.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace clothlab {
namespace {

constexpr int kLanczosSteps = 48;

// Deterministic start vector in [-1, 1] (splitmix64): every run estimates the same value.
double start_value(std::uint64_t i) {
  std::uint64_t z = i * 0x9e3779b97f4a7c15ULL + 0x632be59bd9b4e019ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * (2.0 / 9007199254740992.0) - 1.0;
}

// S = M^-1/2 A M^-1/2 restricted to the free vertices, where A assembles w d d^T per spring
// (w = stiffness or damping, d the rest direction): y = S x, x and y 3 n long (xyz interleaved).
struct SpringOperator {
  std::vector<std::array<int, 2>> ends;
  std::vector<std::array<double, 3>> dir;
  std::vector<double> weight;
  std::vector<double> inv_sqrt_mass;  // 0 for pinned vertices: restricts S to the free ones

  void apply(const std::vector<double>& x, std::vector<double>& y) const {
    std::fill(y.begin(), y.end(), 0.0);
    for (std::size_t s = 0; s < ends.size(); ++s) {
      const auto a = static_cast<std::size_t>(ends[s][0]), b = static_cast<std::size_t>(ends[s][1]);
      const double sa = inv_sqrt_mass[a], sb = inv_sqrt_mass[b];
      const auto& d = dir[s];
      double stretch = 0.0;  // d . (u_b - u_a) with u = M^-1/2 x
      for (int c = 0; c < 3; ++c) stretch += d[c] * (sb * x[3 * b + c] - sa * x[3 * a + c]);
      const double t = weight[s] * stretch;
      for (int c = 0; c < 3; ++c) {
        y[3 * a + c] -= sa * t * d[c];
        y[3 * b + c] += sb * t * d[c];
      }
    }
  }
};

// The largest eigenvalue of the symmetric positive semi-definite operator by Lanczos.
double largest_eigenvalue(const SpringOperator& op, std::size_t n) {
  const std::size_t dim = 3 * n;
  std::vector<double> q(dim), q_prev(dim, 0.0), w(dim);
  double norm = 0.0;
  for (std::size_t k = 0; k < dim; ++k) {
    q[k] = op.inv_sqrt_mass[k / 3] > 0.0 ? start_value(k) : 0.0;
    norm += q[k] * q[k];
  }
  if (norm == 0.0) return 0.0;
  for (double& v : q) v /= std::sqrt(norm);
  std::vector<double> alpha, beta;
  double beta_prev = 0.0;
  for (int j = 0; j < kLanczosSteps; ++j) {
    op.apply(q, w);
    double a = 0.0;
    for (std::size_t k = 0; k < dim; ++k) a += q[k] * w[k];
    double b = 0.0;
    for (std::size_t k = 0; k < dim; ++k) {
      w[k] -= a * q[k] + beta_prev * q_prev[k];
      b += w[k] * w[k];
    }
    b = std::sqrt(b);
    alpha.push_back(a);
    if (b < 1e-12 * std::max(1.0, std::abs(a))) break;  // an invariant subspace: exact
    beta.push_back(b);
    for (std::size_t k = 0; k < dim; ++k) {
      q_prev[k] = q[k];
      q[k] = w[k] / b;
    }
    beta_prev = b;
  }
  const auto m = static_cast<Eigen::Index>(alpha.size());
  Eigen::VectorXd diag = Eigen::Map<Eigen::VectorXd>(alpha.data(), m);
  Eigen::VectorXd sub = Eigen::VectorXd::Zero(std::max<Eigen::Index>(m - 1, 0));
  for (Eigen::Index k = 0; k + 1 < m; ++k) sub[k] = beta[static_cast<std::size_t>(k)];
  if (m == 1) return std::max(0.0, diag[0]);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig;
  eig.computeFromTridiagonal(diag, sub, Eigen::EigenvaluesOnly);
  return std::max(0.0, eig.eigenvalues()[m - 1]);  // sorted ascending
}

}  // namespace

template <class T>
Spectrum estimate_spectrum(const Model<T>& m) {
  const SpringList<T> springs = spring_list(m);
  SpringOperator stiff;
  stiff.ends = springs.ends;
  stiff.dir.resize(springs.size());
  stiff.inv_sqrt_mass.resize(m.n);
  double min_free_mass = INFINITY;
  for (std::size_t i = 0; i < m.n; ++i) {
    const bool free = m.inv_mass[i] != T(0);
    stiff.inv_sqrt_mass[i] = free ? 1.0 / std::sqrt(double(m.mass[i])) : 0.0;
    if (free) min_free_mass = std::min(min_free_mass, double(m.mass[i]));
  }
  const Vec3Array<T>& x = m.rest_positions;
  std::vector<double> row_bound(3 * m.n, 0.0);  // Gershgorin: absolute row sums of S
  for (std::size_t s = 0; s < springs.size(); ++s) {
    const auto a = static_cast<std::size_t>(springs.ends[s][0]);
    const auto b = static_cast<std::size_t>(springs.ends[s][1]);
    std::array<double, 3> d{double(x.x[b]) - x.x[a], double(x.y[b]) - x.y[a],
                            double(x.z[b]) - x.z[a]};
    const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (double& c : d) c = len > 0.0 ? c / len : 0.0;
    stiff.dir[s] = d;
    const double k = double(springs.stiffness[s]);
    const double abs_sum = std::abs(d[0]) + std::abs(d[1]) + std::abs(d[2]);
    const double sa = stiff.inv_sqrt_mass[a], sb = stiff.inv_sqrt_mass[b];
    for (int c = 0; c < 3; ++c) {
      row_bound[3 * a + c] += k * std::abs(d[c]) * abs_sum * sa * (sa + sb);
      row_bound[3 * b + c] += k * std::abs(d[c]) * abs_sum * sb * (sa + sb);
    }
  }
  SpringOperator damp = stiff;
  stiff.weight.assign(springs.stiffness.begin(), springs.stiffness.end());
  damp.weight.assign(springs.damping.begin(), springs.damping.end());

  Spectrum out;
  out.omega_max = std::sqrt(largest_eigenvalue(stiff, m.n));
  out.omega_gershgorin = std::sqrt(*std::max_element(row_bound.begin(), row_bound.end()));
  const bool damped =
      std::any_of(damp.weight.begin(), damp.weight.end(), [](double c) { return c != 0.0; });
  out.gamma_max = damped ? largest_eigenvalue(damp, m.n) : 0.0;
  if (std::isfinite(min_free_mass)) out.gamma_max += double(m.drag) / min_free_mass;
  return out;
}

template Spectrum estimate_spectrum<float>(const Model<float>&);
template Spectrum estimate_spectrum<double>(const Model<double>&);

}  // namespace clothlab
