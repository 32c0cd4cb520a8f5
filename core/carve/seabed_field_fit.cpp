#include "carve/seabed_field_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include "carve/internal/seabed_rays.h"
#include "sonar/beam_pattern.h"

namespace sonarcarve {
namespace {

using namespace seabed_internal;

constexpr double kStep_rad = 0.2 * std::numbers::pi / 180.0;
constexpr int kBeamStride = 4;
// A pixel over this many times the median of its range bin over the fan's lit beams holds
// structure, which the seabed does not explain. Told from the frame alone, so that a surface
// cannot leave pixels out by predicting them wrong.
constexpr float kStructureFactor = 4.0f;

// Per range bin, the level over which a pixel of the fit's beams holds structure (+inf where
// no beam is lit).
std::vector<float> structureLevels(const cv::Mat& pixels, const BeamRays& rays) {
  std::vector<float> levels(static_cast<std::size_t>(pixels.rows),
                            std::numeric_limits<float>::infinity());
  std::vector<float> lit;
  for (int r = 0; r < pixels.rows; ++r) {
    lit.clear();
    for (const int b : rays.beams) {
      if (pixels.at<float>(r, b) > 0.0f) {
        lit.push_back(pixels.at<float>(r, b));
      }
    }
    if (lit.size() * 2 > rays.beams.size()) {
      const auto mid = lit.begin() + static_cast<std::ptrdiff_t>(lit.size() / 2);
      std::nth_element(lit.begin(), mid, lit.end());
      levels[static_cast<std::size_t>(r)] = kStructureFactor * *mid;
    }
  }
  return levels;
}

// Where one beam's interval ends meet the surface: the range (+inf where the end misses it) and
// d range / d depth of the seabed there (0 where the plane, not the relief, answered).
struct EndHit {
  double range = std::numeric_limits<double>::infinity();
  double slope = 0.0;  // d z / d r of the ray less the relief's: > 0 where it meets it
  std::size_t nodes[4] = {0, 0, 0, 0};
  double weights[4] = {0.0, 0.0, 0.0, 0.0};
  bool on_field = false;
};

EndHit hitEnd(const SeabedSurface& surface, const Eigen::Vector3d& position,
              const Eigen::Vector3d& direction) {
  EndHit hit;
  hit.range = surface.rayRange(position, direction);
  if (!std::isfinite(hit.range) || surface.field == nullptr) {
    return hit;
  }
  const Eigen::Vector3d p = position + hit.range * direction;
  if (!surface.field->covers(p.x(), p.y())) {
    return hit;
  }
  Eigen::Vector2d grad;
  surface.field->depthAt(p.x(), p.y(), &grad);
  hit.slope = direction.z() - grad.dot(direction.head<2>());
  if (!(hit.slope > 0.02)) {
    return hit;
  }
  surface.field->stencil(p.x(), p.y(), hit.nodes, hit.weights);
  hit.on_field = true;
  return hit;
}

// One pixel's residual (observed less the gain times the prediction) and its derivative
// with respect to the depths of the nodes it depends on.
struct ResidualRow {
  double residual = 0.0;
  std::vector<std::pair<std::size_t, double>> jacobian;
};

// One beam's misfit and, where asked, its used pixels' residual rows.
struct BeamMisfit {
  SeabedMisfit misfit;
  std::vector<ResidualRow> rows;
};

BeamMisfit beamMisfit(const cv::Mat& pixels, const float* structure, const BeamRays& rays,
                      std::size_t i, const SeabedSurface& surface, const Eigen::Vector3d& position,
                      const RangeBins& bins, bool want_gradient) {
  BeamMisfit out;
  const int rows = pixels.rows;
  const int beam = rays.beams[i];
  const auto n = static_cast<std::size_t>(rays.intervals);
  const Eigen::Vector3d* ends = rays.ends.data() + i * (n + 1);
  const Eigen::Vector3d* centres = rays.centres.data() + i * n;
  std::vector<EndHit> hits(n + 1);
  for (std::size_t k = 0; k <= n; ++k) {
    hits[k] = hitEnd(surface, position, ends[k]);
  }
  // The intervals as accumulateOnSurface deposits them, and how each one's weight moves with
  // the nodes of the cell its centre meets.
  struct Interval : SurfaceInterval {
    bool on_field = false;  // whether the weight's cos(incidence) is the relief's
    std::size_t centre_nodes[4] = {0, 0, 0, 0};
    double dweight_dnode[4] = {0.0, 0.0, 0.0, 0.0};
  };
  std::vector<double> end_ranges(n + 1);
  for (std::size_t k = 0; k <= n; ++k) {
    end_ranges[k] = hits[k].range;
  }
  std::vector<Interval> intervals;
  intervals.reserve(n);
  std::vector<float> column(static_cast<std::size_t>(rows), 0.0f);
  for (const SurfaceInterval& base : surfaceIntervals(rays, i, surface, position, end_ranges)) {
    Interval iv;
    static_cast<SurfaceInterval&>(iv) = base;
    const Eigen::Vector3d& c = base.centre_hit;
    if (want_gradient && surface.field != nullptr && surface.field->covers(c.x(), c.y())) {
      // cos(incidence) = -n . d, n = (gn, ge, -1) / |.|, (gn, ge) the relief's gradient there,
      // which each of the cell's nodes moves linearly.
      Eigen::Vector2d g;
      surface.field->depthAt(c.x(), c.y(), &g);
      const Eigen::Vector3d& d = centres[base.k];
      const double norm = std::sqrt(g.squaredNorm() + 1.0);
      const double a = g.x() * d.x() + g.y() * d.y() - d.z();
      const double dcos_dn = -d.x() / norm + a * g.x() / (norm * norm * norm);
      const double dcos_de = -d.y() / norm + a * g.y() / (norm * norm * norm);
      double d_north[4], d_east[4];
      surface.field->gradientStencil(c.x(), c.y(), iv.centre_nodes, d_north, d_east);
      for (int s = 0; s < 4; ++s) {
        iv.dweight_dnode[s] = rays.weights[base.k] * (dcos_dn * d_north[s] + dcos_de * d_east[s]);
      }
      iv.on_field = true;
    }
    depositInterval(column, iv.r0, iv.r1, iv.weight, bins);
    intervals.push_back(iv);
  }
  // The beam's own gain over the pixels that are not structure's.
  const auto isUsed = [&](int r) { return !(pixels.at<float>(r, beam) > structure[r]); };
  double op = 0.0, pp = 0.0;
  for (int r = 0; r < rows; ++r) {
    if (isUsed(r)) {
      const double p = column[static_cast<std::size_t>(r)];
      op += pixels.at<float>(r, beam) * p;
      pp += p * p;
    }
  }
  const double gain = pp > 0.0 ? op / pp : 0.0;
  for (int r = 0; r < rows; ++r) {
    if (!isUsed(r)) {
      continue;
    }
    const double o = pixels.at<float>(r, beam);
    const double res = o - gain * column[static_cast<std::size_t>(r)];
    out.misfit.residual += res * res;
    out.misfit.energy += o * o;
  }
  if (!want_gradient || !(out.misfit.energy > 0.0)) {
    return out;
  }
  // d P(bin) / d node depth, per bin: through the even spread of each interval over its
  // ranges [lo, hi] (bins) and through its weight's cos(incidence).
  std::vector<std::vector<std::pair<std::size_t, double>>> jacobian(static_cast<std::size_t>(rows));
  const double inv_res = 1.0 / bins.resolution_m;
  const auto addEnd = [&](int bin, const EndHit& hit, double dp_dbin_of_end) {
    // d range / d depth of a node under the end = its bilinear weight / slope.
    const double dp_dr = dp_dbin_of_end * inv_res / hit.slope;
    for (int s = 0; s < 4; ++s) {
      if (hit.weights[s] > 0.0) {
        jacobian[static_cast<std::size_t>(bin)].emplace_back(hit.nodes[s], dp_dr * hit.weights[s]);
      }
    }
  };
  for (std::size_t m = 0; m < intervals.size(); ++m) {
    const Interval& iv = intervals[m];
    const double lo = (std::min(iv.r0, iv.r1) - bins.min_m) * inv_res;
    const double hi = (std::max(iv.r0, iv.r1) - bins.min_m) * inv_res;
    if (hi < 0.0 || lo >= rows) {
      continue;
    }
    const std::size_t k = iv.k;
    const bool first_is_lo = iv.r0 <= iv.r1;
    const EndHit* lo_end =
        first_is_lo ? (iv.own0 ? &hits[k] : nullptr) : (iv.own1 ? &hits[k + 1] : nullptr);
    const EndHit* hi_end =
        first_is_lo ? (iv.own1 ? &hits[k + 1] : nullptr) : (iv.own0 ? &hits[k] : nullptr);
    if (hi - lo < 1e-6) {
      // All in one bin: only the weight moves what it deposits.
      const int b = std::clamp(static_cast<int>(lo), 0, rows - 1);
      for (int s = 0; iv.on_field && s < 4; ++s) {
        jacobian[static_cast<std::size_t>(b)].emplace_back(iv.centre_nodes[s], iv.dweight_dnode[s]);
      }
      continue;
    }
    const double span = hi - lo;
    const int b_lo = static_cast<int>(std::floor(lo));
    const int b_hi = static_cast<int>(std::floor(hi));
    for (int b = std::max(0, b_lo); b < std::min(hi, static_cast<double>(rows)); ++b) {
      const double overlap = std::min(hi, b + 1.0) - std::max(lo, static_cast<double>(b));
      // P_b = W overlap_b / span: d/d hi = W (1[b holds hi] / span - overlap_b / span^2),
      // d/d lo = W (overlap_b / span^2 - 1[b holds lo] / span), d/d W = overlap_b / span.
      const double shared = iv.weight * overlap / (span * span);
      if (hi_end != nullptr && hi_end->on_field) {
        addEnd(b, *hi_end, (b == b_hi ? iv.weight / span : 0.0) - shared);
      }
      if (lo_end != nullptr && lo_end->on_field) {
        addEnd(b, *lo_end, shared - (b == b_lo ? iv.weight / span : 0.0));
      }
      for (int s = 0; iv.on_field && s < 4; ++s) {
        jacobian[static_cast<std::size_t>(b)].emplace_back(iv.centre_nodes[s],
                                                           overlap / span * iv.dweight_dnode[s]);
      }
    }
  }
  // Per used bin: the residual and d residual / d node (= -gain d P / d node), nodes merged.
  for (int r = 0; r < rows; ++r) {
    auto& row = jacobian[static_cast<std::size_t>(r)];
    if (!isUsed(r) || row.empty()) {
      continue;
    }
    std::sort(row.begin(), row.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    std::size_t kept = 0;
    for (std::size_t e = 0; e < row.size(); ++e) {
      if (kept > 0 && row[kept - 1].first == row[e].first) {
        row[kept - 1].second += row[e].second;
      } else {
        row[kept++] = row[e];
      }
    }
    row.resize(kept);
    ResidualRow out_row;
    out_row.residual = pixels.at<float>(r, beam) - gain * column[static_cast<std::size_t>(r)];
    for (const auto& [node, dp] : row) {
      out_row.jacobian.emplace_back(node, -gain * dp);
    }
    out.rows.push_back(std::move(out_row));
  }
  return out;
}

}  // namespace

namespace {

// Where a frame's main lobe (inside the -3 dB aperture: 33 beams across the fan, 9 elevations)
// meets its plane within the range window, and the beam's power there.
struct LobeHit {
  Eigen::Vector2d at;
  double power;
};

std::vector<LobeHit> mainLobeHits(const SeabedFrame& f, const SonarModel& sonar) {
  constexpr int kElevations = 9;
  constexpr int kBeams = 33;
  const SincSquaredBeam beam(sonar.verticalAperture());
  const double half = 0.5 * sonar.verticalAperture();
  const double near = sonar.range().min_m;
  const double far = sonar.range().maxRange();
  std::vector<LobeHit> hits;
  for (int b = 0; b < kBeams; ++b) {
    const int col = (sonar.cols() - 1) * b / (kBeams - 1);
    const double bearing = sonar.bearings().centre(col);
    for (int e = 0; e < kElevations; ++e) {
      const double el = -half + 2.0 * half * e / (kElevations - 1);
      const Eigen::Vector3d d = f.T_world_sonar.linear() * rayDirection(el, bearing);
      const double r = SeabedSurface{f.plane}.rayRange(f.T_world_sonar.translation(), d);
      if (r >= near && r <= far) {
        hits.push_back({(f.T_world_sonar.translation() + r * d).head<2>(), beam.power(el)});
      }
    }
  }
  return hits;
}

}  // namespace

SeabedHeightfield fuseSeabedPlanes(const std::vector<SeabedFrame>& frames, const SonarModel& sonar,
                                   double cell_m) {
  // A node is known once this much of the beams' power met the planes around it (about two
  // rays on the beam's axis): where the rays thin out at the fan's far edges, its plane's
  // extrapolation is left to the frame.
  constexpr double kMinFusedWeight = 0.5;
  // Where the frames' main lobes meet their planes, weighted by the beam's power.
  struct Sample {
    Eigen::Vector2d at;
    double depth, weight;
  };
  std::vector<Sample> samples;
  Eigen::AlignedBox2d box;
  for (const SeabedFrame& f : frames) {
    for (const LobeHit& hit : mainLobeHits(f, sonar)) {
      samples.push_back({hit.at, f.plane.depthAt(hit.at.x(), hit.at.y()), hit.power});
      box.extend(hit.at);
    }
  }
  if (box.isEmpty()) {
    return SeabedHeightfield(Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(), cell_m);
  }
  const Eigen::Vector2d margin = Eigen::Vector2d::Constant(2.0 * cell_m);
  SeabedHeightfield field(box.min() - margin, box.max() + margin, cell_m);
  for (const Sample& s : samples) {
    field.add(s.at.x(), s.at.y(), s.depth, s.weight);
  }
  field.finish(kMinFusedWeight);
  return field;
}

namespace {

// A frame's beams' misfits and, where asked, their residual rows.
std::vector<BeamMisfit> frameMisfits(const cv::Mat& pixels, const SeabedSurface& surface,
                                     const Eigen::Isometry3d& T_world_sonar,
                                     const SonarModel& sonar, bool want_rows, ThreadPool* pool) {
  const BeamRays rays = beamRays(sonar, T_world_sonar.linear(), kBeamStride, kStep_rad, pool);
  const std::vector<float> structure = structureLevels(pixels, rays);
  std::vector<BeamMisfit> beams(rays.beams.size());
  forEachBeam(pool, rays.beams.size(), [&](std::size_t i) {
    beams[i] = beamMisfit(pixels, structure.data(), rays, i, surface, T_world_sonar.translation(),
                          sonar.range(), want_rows);
  });
  return beams;
}

SeabedMisfit sum(const std::vector<BeamMisfit>& beams) {
  SeabedMisfit total;
  for (const BeamMisfit& b : beams) {
    total.residual += b.misfit.residual;
    total.energy += b.misfit.energy;
  }
  return total;
}

// The Gauss-Newton normal equations J'J and J'e of the relief's nodes, J'J held per node for
// its neighbours within kReach nodes (a pixel's return comes from rays a few centimetres
// apart, so its nodes are neighbours; couplings further apart are dropped).
constexpr int kReach = 2;
constexpr int kSide = 2 * kReach + 1;

struct NormalEquations {
  explicit NormalEquations(const SeabedHeightfield& field)
      : nx(field.columns()),
        jtj(field.nodeCount() * kSide * kSide, 0.0),
        jte(field.nodeCount(), 0.0) {}
  void add(const ResidualRow& row) {
    for (const auto& [a, va] : row.jacobian) {
      jte[a] += va * row.residual;
      const int ia = static_cast<int>(a % static_cast<std::size_t>(nx));
      const int ja = static_cast<int>(a / static_cast<std::size_t>(nx));
      for (const auto& [b, vb] : row.jacobian) {
        const int di = static_cast<int>(b % static_cast<std::size_t>(nx)) - ia;
        const int dj = static_cast<int>(b / static_cast<std::size_t>(nx)) - ja;
        if (std::abs(di) <= kReach && std::abs(dj) <= kReach) {
          jtj[a * kSide * kSide + static_cast<std::size_t>((dj + kReach) * kSide + di + kReach)] +=
              va * vb;
        }
      }
    }
  }
  int nx;
  std::vector<double> jtj, jte;
};

// Solves (J'J + damping diag + smoothness L) step = -J'e - smoothness L depth over the known
// nodes; the others do not move.
std::vector<double> gaussNewtonStep(const NormalEquations& ne, const SeabedHeightfield& field,
                                    double damping, double smoothness) {
  const std::size_t n = field.nodeCount();
  const int nx = field.columns(), ny = field.rows();
  std::vector<int> unknown(n, -1);
  int count = 0;
  std::vector<double> diagonal;
  for (std::size_t i = 0; i < n; ++i) {
    if (field.known(i)) {
      unknown[i] = count++;
      const double d = ne.jtj[i * kSide * kSide + kReach * kSide + kReach];
      if (d > 0.0) {
        diagonal.push_back(d);
      }
    }
  }
  std::vector<double> step(n, 0.0);
  if (count == 0 || diagonal.empty()) {
    return step;
  }
  std::nth_element(diagonal.begin(),
                   diagonal.begin() + static_cast<std::ptrdiff_t>(diagonal.size() / 2),
                   diagonal.end());
  const double typical = diagonal[diagonal.size() / 2];
  const double mu = smoothness * typical;
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(count);
  const std::vector<double>& depth = field.depths();
  for (std::size_t i = 0; i < n; ++i) {
    const int u = unknown[i];
    if (u < 0) {
      continue;
    }
    const int ii = static_cast<int>(i % static_cast<std::size_t>(nx));
    const int ji = static_cast<int>(i / static_cast<std::size_t>(nx));
    rhs[u] = -ne.jte[i];
    for (int dj = -kReach; dj <= kReach; ++dj) {
      for (int di = -kReach; di <= kReach; ++di) {
        const double v = ne.jtj[i * kSide * kSide +
                                static_cast<std::size_t>((dj + kReach) * kSide + di + kReach)];
        const int i2 = ii + di, j2 = ji + dj;
        if (v == 0.0 || i2 < 0 || j2 < 0 || i2 >= nx || j2 >= ny) {
          continue;
        }
        const int u2 = unknown[static_cast<std::size_t>(j2) * static_cast<std::size_t>(nx) +
                               static_cast<std::size_t>(i2)];
        if (u2 >= 0) {
          triplets.emplace_back(u, u2, v);
        }
      }
    }
    const double d = ne.jtj[i * kSide * kSide + kReach * kSide + kReach];
    triplets.emplace_back(u, u, damping * d + 1e-6 * typical);
    // The membrane between neighbours along north and east.
    for (const auto& [di, dj] :
         {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}}) {
      const int i2 = ii + di, j2 = ji + dj;
      if (i2 < 0 || j2 < 0 || i2 >= nx || j2 >= ny) {
        continue;
      }
      const std::size_t m = static_cast<std::size_t>(j2) * static_cast<std::size_t>(nx) +
                            static_cast<std::size_t>(i2);
      const int u2 = unknown[m];
      if (u2 < 0) {
        continue;
      }
      triplets.emplace_back(u, u, mu);
      triplets.emplace_back(u, u2, -mu);
      rhs[u] -= mu * (depth[i] - depth[m]);
    }
  }
  Eigen::SparseMatrix<double> A(count, count);
  A.setFromTriplets(triplets.begin(), triplets.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(A);
  if (solver.info() != Eigen::Success) {
    return step;
  }
  const Eigen::VectorXd x = solver.solve(rhs);
  for (std::size_t i = 0; i < n; ++i) {
    if (unknown[i] >= 0 && std::isfinite(x[unknown[i]])) {
      step[i] = x[unknown[i]];
    }
  }
  return step;
}

}  // namespace

double reliefDeparture(const SeabedFrame& frame, const SeabedHeightfield& field,
                       const SonarModel& sonar) {
  double sum = 0.0, weight = 0.0;
  for (const LobeHit& hit : mainLobeHits(frame, sonar)) {
    if (field.covers(hit.at.x(), hit.at.y())) {
      const double d =
          field.depthAt(hit.at.x(), hit.at.y()) - frame.plane.depthAt(hit.at.x(), hit.at.y());
      sum += hit.power * d * d;
      weight += hit.power;
    }
  }
  return weight > 0.0 ? std::sqrt(sum / weight) : 0.0;
}

SeabedMisfit seabedFieldMisfit(const cv::Mat& pixels, const SeabedSurface& surface,
                               const Eigen::Isometry3d& T_world_sonar, const SonarModel& sonar,
                               std::vector<double>* gradient, ThreadPool* pool) {
  const std::vector<BeamMisfit> beams =
      frameMisfits(pixels, surface, T_world_sonar, sonar, gradient != nullptr, pool);
  const SeabedMisfit total = sum(beams);
  if (gradient != nullptr && total.energy > 0.0) {
    // d (sum of e^2 / energy) / d node = 2 e (d e / d node) / energy.
    const double norm = 2.0 / total.energy;
    for (const BeamMisfit& b : beams) {
      for (const ResidualRow& row : b.rows) {
        for (const auto& [node, de] : row.jacobian) {
          (*gradient)[node] += norm * row.residual * de;
        }
      }
    }
  }
  return total;
}

SeabedFieldFitResult fitSeabedField(SeabedHeightfield& field,
                                    const std::vector<SeabedFrame>& frames,
                                    const std::function<cv::Mat(std::size_t)>& pixels_of,
                                    const SonarModel& sonar, const SeabedFieldFitParams& params,
                                    ThreadPool* pool, Progress& progress) {
  SeabedFieldFitResult result;
  const std::vector<double> start = field.depths();
  const std::size_t work = static_cast<std::size_t>(params.passes) * frames.size();
  std::size_t done = 0;
  for (int pass = 0; pass < params.passes; ++pass) {
    NormalEquations equations(field);
    SeabedMisfit this_pass;
    for (std::size_t n = 0; n < frames.size(); ++n) {
      if (progress.cancelled()) {
        result.cancelled = true;
        return result;
      }
      const cv::Mat pixels = pixels_of(n);
      if (!pixels.empty()) {
        const std::vector<BeamMisfit> beams =
            frameMisfits(pixels, SeabedSurface{frames[n].plane, &field}, frames[n].T_world_sonar,
                         sonar, true, pool);
        const SeabedMisfit m = sum(beams);
        if (m.energy > 0.0) {
          // Each frame counts by its misfit's share, whatever its brightness.
          const double w = 1.0 / std::sqrt(m.energy);
          for (const BeamMisfit& b : beams) {
            for (ResidualRow row : b.rows) {
              row.residual *= w;
              for (auto& entry : row.jacobian) {
                entry.second *= w;
              }
              equations.add(row);
            }
          }
        }
        this_pass.residual += m.residual;
        this_pass.energy += m.energy;
      }
      progress.report("seabed relief", ++done, work);
    }
    if (pass == 0) {
      result.misfit_before = this_pass.misfit();
    }
    result.misfit_after = this_pass.misfit();
    const std::vector<double> step =
        gaussNewtonStep(equations, field, params.damping, params.smoothness);
    std::vector<double>& depth = field.depths();
    for (std::size_t i = 0; i < depth.size(); ++i) {
      depth[i] = std::clamp(depth[i] + std::clamp(step[i], -params.max_step_m, params.max_step_m),
                            start[i] - params.max_move_m, start[i] + params.max_move_m);
    }
    ++result.steps;
  }
  return result;
}

}  // namespace sonarcarve
