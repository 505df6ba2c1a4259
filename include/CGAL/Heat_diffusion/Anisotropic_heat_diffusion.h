// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Conservative multi-scale diffusion by local heat kernel convolution: paper, section 5.

#ifndef CGAL_HEAT_DIFFUSION_ANISOTROPIC_HEAT_DIFFUSION_H
#define CGAL_HEAT_DIFFUSION_ANISOTROPIC_HEAT_DIFFUSION_H

#include <CGAL/Heat_diffusion/Edge_weighted_heat_kernel.h>
#include <CGAL/Heat_diffusion/internal/parallel_for.h>
#include <CGAL/Heat_diffusion/parameters.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {

/// \ingroup PkgHeatDiffusionDiffusion
/// Statistics of the heat regions \f$ \Omega_j \f$ of an `Anisotropic_heat_diffusion`.
struct Heat_region_statistics
{
  std::size_t min_size = 0;          ///< the smallest region, in vertices
  double mean_size = 0;              ///< the mean region size
  std::size_t max_size = 0;          ///< the largest region
  std::size_t collapsed_regions = 0; ///< regions reduced to their source vertex: it keeps its heat
  std::size_t capped_regions = 0;    ///< regions that reached `Anisotropic_heat_diffusion::maximum_region_size`
};

/// \ingroup PkgHeatDiffusionDiffusion
/// The diffusion operator \f$ A_t \f$ of the paper (eq. 15-19) built once, and
/// \f$ F^k = A_t^k F^0 \f$ computed many times by sparse matrix-vector products.
///
/// <b>Heat regions (eq. 15).</b> The region \f$ \Omega_j \f$ of a vertex \f$ v_j \f$ is grown
/// breadth first from \f$ v_j \f$ over mesh edges, taking the vertices with
/// \f$ h_t(j, i) > \tau(t) = 0.01/(1+t) \f$ and never expanding through a vertex at or
/// below the threshold; \f$ v_j \f$ always belongs. For the scale-invariant kernel (eq. 14),
/// whose values live on another scale, the threshold is relative to the column's peak,
/// \f$ h_t(j, i) > \tau(t)\, h_t(j, j) \f$: with the absolute threshold every region
/// would collapse to its source vertex. Growing from the source keeps the regions local
/// even where the truncated kernel oscillates far away.
///
/// <b>Normalisation (eq. 16-18, corrected).</b> Vertex \f$ v_j \f$ hands its heat to its own
/// region: \f$ A_t(i, j) = h_t(j, i) / \sum_{k \in \Omega_j} h_t(j, k) \f$ for \f$ i \in \Omega_j \f$.
/// Every column of \f$ A_t \f$ sums to 1 and all entries are positive, so the total heat
/// \f$ \sum_i F^k(i) \f$ is conserved exactly (up to rounding) for every k. (The paper
/// normalises over \f$ \Omega_i \f$, which conserves nothing unless the regions happen to be
/// symmetric.)
///
/// <b>Capped regions.</b> A kernel that is nearly flat (the scale-invariant kernel at
/// t = 1, whose time unit is \f$ 1/\lambda_\ast \f$, is nearly constant over fandisk) would
/// give regions as large as the mesh and a dense \f$ A_t \f$. Regions stop growing at
/// `maximum_region_size` vertices (breadth first, so the nearest are kept);
/// the normalisation, and so the conservation, is unchanged. `region_statistics()`
/// counts capped regions.
///
/// <b>Collapsed regions.</b> When the kernel of a vertex is below the threshold at all
/// its neighbours (the truncated kernel can be that flat at small t), its region is the
/// vertex alone and it never diffuses. `region_statistics()` counts such regions.
///
/// @tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// @tparam GeomTraits a model of `Kernel`
template <typename TriangleMesh,
          typename GeomTraits = typename CGAL::Kernel_traits<typename boost::property_traits<
              typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type>::Kernel>
class Anisotropic_heat_diffusion
{
public:
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef Edge_weighted_heat_kernel<TriangleMesh, GeomTraits> Heat_kernel;
  /// The sparse matrix type of \f$ A_t \f$.
  typedef Eigen::SparseMatrix<double> Sparse_matrix;

  /// Builds the heat kernel of `tm` (see `Edge_weighted_heat_kernel` for its named
  /// parameters) and \f$ A_t \f$ for the named parameter `time` (default 1).
  template <typename NamedParameters = parameters::Default_named_parameters>
  explicit Anisotropic_heat_diffusion(const TriangleMesh& tm, const NamedParameters& np = parameters::default_values())
    : owned_kernel_(std::make_shared<Heat_kernel>(tm, np)), kernel_(*owned_kernel_)
  {
    build(parameters::choose_parameter(parameters::get_parameter(np, internal_np::time), 1.));
  }

  /// Builds \f$ A_t \f$ from an existing kernel, which must outlive this object.
  ///
  /// \throws std::invalid_argument if `t` is not positive and finite.
  ///
  /// Complexity: linear in the number of vertices for a fixed t (one breadth-first
  /// search per vertex, over its region and the region's one-ring; parallel with TBB).
  Anisotropic_heat_diffusion(const Heat_kernel& kernel, double t) : kernel_(kernel) { build(t); }

  /// The largest heat region, in vertices.
  static constexpr std::size_t maximum_region_size = 4096;

  /// The diffusion time t of one step.
  double time() const { return time_; }
  /// The threshold \f$ \tau(t) = 0.01/(1+t) \f$.
  double threshold() const { return 0.01 / (1. + time_); }
  /// The heat kernel.
  const Heat_kernel& heat_kernel() const { return kernel_; }
  /// \f$ A_t \f$, column-stochastic; rows and columns follow `Heat_kernel::vertex_index()`.
  const Sparse_matrix& operator_matrix() const { return operator_; }
  /// Sizes of the heat regions.
  const Heat_region_statistics& region_statistics() const { return statistics_; }

  /// \f$ F^k = A_t^k F^0 \f$ for a field given by vertex index.
  Eigen::VectorXd diffuse(const Eigen::VectorXd& field, std::size_t number_of_steps) const
  {
    check_field(field);
    Eigen::VectorXd current = field, next(field.size());
    for(std::size_t k = 0; k < number_of_steps; ++k)
    {
      step(current, next);
      current.swap(next);
    }
    return current;
  }

  /// The fields \f$ F^k \f$ for every k of `steps` (in any order), in one pass.
  std::vector<Eigen::VectorXd> diffuse(const Eigen::VectorXd& field, const std::vector<std::size_t>& steps) const
  {
    check_field(field);
    std::vector<Eigen::VectorXd> result(steps.size());
    const std::size_t last = steps.empty() ? 0 : *std::max_element(steps.begin(), steps.end());
    Eigen::VectorXd current = field, next(field.size());
    for(std::size_t k = 0;; ++k)
    {
      for(std::size_t s = 0; s < steps.size(); ++s)
        if(steps[s] == k)
          result[s] = current;
      if(k == last)
        break;
      step(current, next);
      current.swap(next);
    }
    return result;
  }

  /// Diffuses the field `field_in` by `number_of_steps` steps and writes it to `field_out`.
  /// @tparam InputFieldMap a model of `ReadablePropertyMap`, `vertex_descriptor` to a floating-point type
  /// @tparam OutputFieldMap a model of `WritablePropertyMap`, `vertex_descriptor` to a floating-point type
  /// \throws std::invalid_argument if a value of `field_in` is not finite.
  template <typename InputFieldMap, typename OutputFieldMap>
  void diffuse(InputFieldMap field_in, OutputFieldMap field_out, std::size_t number_of_steps) const
  {
    const TriangleMesh& tm = kernel_.normal_controlled_coordinates().mesh();
    Eigen::VectorXd field(Eigen::Index(kernel_.number_of_vertices()));
    for(vertex_descriptor v : vertices(tm))
      field[Eigen::Index(kernel_.vertex_index(v))] = CGAL::to_double(get(field_in, v));
    const Eigen::VectorXd result = diffuse(field, number_of_steps);
    typedef typename boost::property_traits<OutputFieldMap>::value_type Value;
    for(vertex_descriptor v : vertices(tm))
      put(field_out, v, Value(result[Eigen::Index(kernel_.vertex_index(v))]));
  }

private:
  void check_field(const Eigen::VectorXd& field) const
  {
    if(field.size() != Eigen::Index(kernel_.number_of_vertices()))
      internal::throw_invalid_input("Anisotropic_heat_diffusion: the field has the wrong size");
    for(Eigen::Index i = 0; i < field.size(); ++i)
      if(!std::isfinite(field[i]))
      {
        std::ostringstream os;
        os << "Anisotropic_heat_diffusion: the field value at vertex " << i << " is not finite";
        internal::throw_invalid_input(os.str());
      }
  }

  // next = A_t current, row by row (parallel), from the row-major copy.
  void step(const Eigen::VectorXd& current, Eigen::VectorXd& next) const
  {
    internal::parallel_for(std::size_t(row_major_.outerSize()), [&](std::size_t i) {
      double sum = 0;
      for(Row_major::InnerIterator it(row_major_, Eigen::Index(i)); it; ++it)
        sum += it.value() * current[it.index()];
      next[Eigen::Index(i)] = sum;
    });
  }

  void build(double t)
  {
    if(!(t > 0) || !std::isfinite(t))
      internal::throw_invalid_input("Anisotropic_heat_diffusion: time must be positive and finite");
    time_ = t;
    const internal::Indexed_mesh& mesh = kernel_.normal_controlled_coordinates().indexed_mesh();
    const std::size_t n = mesh.number_of_vertices();
    const Eigen::Index m = Eigen::Index(kernel_.number_of_eigenpairs());

    // Psi = Phi exp(-rate t / 2), row-major, so that h_t(i, j) = (beta) Psi_i . Psi_j
    // reads two contiguous rows.
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> psi = kernel_.eigenvectors();
    for(Eigen::Index k = 0; k < m; ++k)
      psi.col(k) *= std::exp(-0.5 * kernel_.decay_rate(std::size_t(k)) * t);
    const bool relative = kernel_.is_scale_invariant();
    auto h = [&](std::size_t i, std::size_t j) {
      const double dot = psi.row(Eigen::Index(i)).dot(psi.row(Eigen::Index(j)));
      return relative ? kernel_.beta(i, j) * dot : dot;
    };

    struct Scratch
    {
      std::vector<std::size_t> mark;  // generation stamps: no clearing between sources
      std::size_t generation = 0;
      std::vector<std::size_t> queue;
    };
    std::vector<std::vector<std::pair<std::size_t, double> > > columns(n);
    internal::parallel_for_with_scratch(
        n, [n] { return Scratch{std::vector<std::size_t>(n, 0), 0, {}}; },
        [&](std::size_t j, Scratch& s) {
          ++s.generation;
          const double peak = h(j, j);
          const double tau = relative ? threshold() * peak : threshold();
          auto& column = columns[j];
          column.clear();
          column.emplace_back(j, peak);
          s.mark[j] = s.generation;
          s.queue.assign(1, j);
          for(std::size_t q = 0; q < s.queue.size() && column.size() < maximum_region_size; ++q)
          {
            const std::size_t i = s.queue[q];
            for(std::size_t k = mesh.fan_begin[i]; k < mesh.fan_begin[i + 1]; ++k)
            {
              const std::size_t u = mesh.fan[k];
              if(s.mark[u] == s.generation)
                continue;
              s.mark[u] = s.generation;
              const double value = h(j, u);
              if(value > tau && column.size() < maximum_region_size)
              {
                column.emplace_back(u, value);
                s.queue.push_back(u);
              }
            }
          }
          // A region whose source value is not positive (possible only for a badly
          // truncated kernel) keeps its heat: a column of the identity.
          double sum = 0;
          for(const auto& entry : column)
            sum += entry.second;
          if(!(column.front().second > 0) || !(sum > 0))
            column.assign(1, {j, 1.});
          else
            for(auto& entry : column)
              entry.second /= sum;
          std::sort(column.begin(), column.end());
        });

    statistics_ = Heat_region_statistics();
    statistics_.min_size = n;
    std::vector<Eigen::Triplet<double> > entries;
    std::size_t total = 0;
    for(const auto& column : columns)
      total += column.size();
    entries.reserve(total);
    for(std::size_t j = 0; j < n; ++j)
    {
      const std::size_t size = columns[j].size();
      statistics_.min_size = (std::min)(statistics_.min_size, size);
      statistics_.max_size = (std::max)(statistics_.max_size, size);
      statistics_.collapsed_regions += size == 1 ? 1 : 0;
      statistics_.capped_regions += size >= maximum_region_size ? 1 : 0;
      for(const auto& entry : columns[j])
        entries.emplace_back(int(entry.first), int(j), entry.second);
    }
    statistics_.mean_size = double(total) / double(n);
    operator_.resize(Eigen::Index(n), Eigen::Index(n));
    operator_.setFromTriplets(entries.begin(), entries.end());
    row_major_ = operator_;
  }

  typedef Eigen::SparseMatrix<double, Eigen::RowMajor> Row_major;

  std::shared_ptr<const Heat_kernel> owned_kernel_;
  const Heat_kernel& kernel_;
  double time_ = 1.;
  Sparse_matrix operator_;
  Row_major row_major_;
  Heat_region_statistics statistics_;
};

/// \ingroup PkgHeatDiffusionDiffusion
/// Diffuses the scalar field `field_in` anisotropically over `tm` and writes
/// \f$ F^k = A_t^k F^0 \f$ to `field_out`: a thin wrapper over
/// `Anisotropic_heat_diffusion` for a single use (build the class to diffuse several
/// fields or to several k without recomputing the kernel).
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{number_of_steps}
///     \cgalParamDescription{the number k of diffusion steps}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{`1`}
///   \cgalParamNEnd
///   \cgalParamNBegin{time}
///     \cgalParamDescription{the time t of one step (on the surface rescaled to area = number of vertices)}
///     \cgalParamType{`double`, positive}
///     \cgalParamDefault{`1`}
///   \cgalParamNEnd
///   \cgalParamNBegin{sigma, number_of_eigenpairs, scale_invariant_kernel, progress_callback, vertex_point_map, ...}
///     \cgalParamDescription{as for `Edge_weighted_heat_kernel`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws std::invalid_argument on invalid input or parameters (a negative k included).
template <typename TriangleMesh, typename InputFieldMap, typename OutputFieldMap,
          typename NamedParameters = parameters::Default_named_parameters>
void anisotropic_heat_diffusion(const TriangleMesh& tm, InputFieldMap field_in, OutputFieldMap field_out,
                                const NamedParameters& np = parameters::default_values())
{
  typedef typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type GeomTraits;
  const auto steps = parameters::choose_parameter(parameters::get_parameter(np, internal_np::number_of_steps), 1);
  if(!(double(steps) >= 0))
    internal::throw_invalid_input("anisotropic_heat_diffusion: number_of_steps must not be negative");
  const Anisotropic_heat_diffusion<TriangleMesh, GeomTraits> diffusion(tm, np);
  diffusion.diffuse(field_in, field_out, std::size_t(steps));
}

} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_ANISOTROPIC_HEAT_DIFFUSION_H
