#include "model/forward_model.h"

#include <cmath>
#include <memory>
#include <mutex>
#include <numbers>

#include "common/error.h"
#include "model/active_cells.h"
#include "model/elevation_fan.h"
#include "model/range_deposit.h"
#include "model/ray_march.h"
#include "model/reflectance.h"

namespace sonarcarve {
namespace {

// Hands each parallel chunk a slot of its own (one per pool thread) for its accumulators.
class Slots {
 public:
  explicit Slots(unsigned count) {
    for (unsigned s = 0; s < count; ++s) {
      free_.push_back(s);
    }
  }
  unsigned take() {
    const std::lock_guard lock(mutex_);
    const unsigned slot = free_.back();
    free_.pop_back();
    return slot;
  }
  void give(unsigned slot) {
    const std::lock_guard lock(mutex_);
    free_.push_back(slot);
  }

 private:
  std::mutex mutex_;
  std::vector<unsigned> free_;
};

cv::Mat backgroundAdded(const cv::Mat& columns, const std::vector<double>& background) {
  cv::Mat frame;
  cv::transpose(columns, frame);
  if (!background.empty()) {
    for (int row = 0; row < frame.rows; ++row) {
      frame.row(row) += background[static_cast<std::size_t>(row)];
    }
  }
  return frame;
}

void checkView(const SonarModel& sonar, const FrameView& view) {
  if (!view.background.empty() && static_cast<int>(view.background.size()) != sonar.rows()) {
    throw Error("forward model", "background", "expected one background value per range bin");
  }
}

}  // namespace

ForwardModel::ForwardModel(const SonarModel& sonar, ModelSettings settings, ThreadPool& pool)
    : sonar_(sonar), settings_(settings), pool_(pool) {
  if (!(settings_.elevation_step_rad > 0.0) || settings_.samples_per_bin < 1 ||
      !(settings_.min_alpha >= 0.0) || !(settings_.min_transmittance >= 0.0) ||
      settings_.beam_stride < 1 || settings_.beam_offset < 0) {
    throw Error("forward model", "settings",
                "expected a positive elevation step, >= 1 sample per bin, thresholds >= 0, a "
                "beam stride >= 1 and an offset >= 0");
  }
}

int ForwardModel::tracedBeams() const {
  const int stride = settings_.beam_stride;
  const int first = settings_.beam_offset;
  return first < sonar_.cols() ? (sonar_.cols() - first + stride - 1) / stride : 0;
}

template <typename RayBody>
void ForwardModel::forEachRay(const BlockGrid& grid, const FrameView& view,
                              const RayBody& body) const {
  checkView(sonar_, view);
  const ElevationFan fan = elevationFan(view.profile.thetaMax(), settings_.elevation_step_rad);
  const double unit_scale = elevationSampleScale(1.0, fan.step_rad, sonar_.verticalAperture(), 1);
  const MarchLimits limits{sonar_.range(), settings_.samples_per_bin, settings_.min_alpha,
                           settings_.min_transmittance};
  const Eigen::Matrix3d R = view.T_world_sonar.linear();
  const Eigen::Vector3d origin = view.T_world_sonar.translation();
  // The cells whose samples can reach min_alpha: the march jumps over the others.
  const ActiveCells active = ActiveCells::reaching(grid, settings_.min_alpha);
  Slots slots(pool_.size());
  const int stride = settings_.beam_stride;
  const int first = settings_.beam_offset;
  const int traced = tracedBeams();
  pool_.parallelFor(static_cast<std::size_t>(traced), 4, [&](std::size_t begin, std::size_t end) {
    const unsigned slot = slots.take();
    StencilReader reader(grid, &active);
    std::vector<RaySample> samples;
    for (auto n = begin; n < end; ++n) {
      ModelRay ray;
      ray.beam = first + static_cast<int>(n) * stride;
      ray.unit_scale = unit_scale;
      ray.scale = view.gain * unit_scale;
      for (int k = 0; k < fan.count; ++k) {
        ray.elevation_rad = fan.angle(k);
        ray.direction_sonar = rayDirection(sonar_.bearings().centre(ray.beam), ray.elevation_rad);
        ray.direction_world = R * ray.direction_sonar;
        ray.power = view.profile.power(ray.elevation_rad);
        ray.beam_weight = solidAngleWeight(ray.power, ray.elevation_rad);
        marchRay(reader, grid.voxelSize(), origin, ray.direction_world, ray.direction_sonar, limits,
                 samples);
        if (!samples.empty()) {
          body(ray, std::span<const RaySample>(samples), slot);
        }
      }
    }
    slots.give(slot);
  });
}

namespace {

// The sums of the gradient of a loss over the rays of one frame, one set per pool thread.
class GradientSums {
 public:
  GradientSums(const BlockGrid& grid, const FrameView& view, const RangeBins& bins,
               const cv::Mat& dloss_dframe, unsigned slots)
      : profile_(view.profile),
        bins_(bins),
        Rt_(view.T_world_sonar.linear().transpose()),
        size_(grid.voxelSize()),
        half_over_size_(0.5 / grid.voxelSize()),
        dloss_(dloss_dframe) {
    for (unsigned s = 0; s < slots; ++s) {
      per_slot_.push_back(std::make_unique<ModelGradient>(
          grid.voxelCount(), view.profile.knotsDb().size(), static_cast<std::size_t>(bins.count)));
    }
    cv::transpose(dloss_dframe, dloss_columns_);
  }

  void add(const ModelRay& ray, std::span<const RaySample> samples, unsigned slot) {
    ModelGradient& out = *per_slot_[slot];
    const auto* dloss = dloss_columns_.ptr<double>(ray.beam);
    const double weight = ray.scale * ray.beam_weight;  // K: I += K * w_i
    const Eigen::Vector3d& d = ray.direction_world;
    double suffix = 0.0;        // S_i: sum over later samples of h a rho c prod (1 - alpha)
    double upstream_sum = 0.0;  // sum over samples of dloss(bin) * w_i
    Eigen::Vector3d dloss_ddirection = Eigen::Vector3d::Zero();
    for (auto it = samples.rbegin(); it != samples.rend(); ++it) {
      const RaySample& s = *it;
      const auto bin = bins_.binOf(s.range_m);
      const double g_pixel = bin ? dloss[*bin] : 0.0;
      const double h = weight * g_pixel;
      const double t = s.transmittance;
      const double a = s.alpha;
      const double rho = s.reflectance;
      const double c = s.cos_incidence;
      upstream_sum += g_pixel * t * a * rho * c;
      const double dalpha = t * (h * rho * c - suffix);
      suffix = h * a * rho * c + (1.0 - a) * suffix;
      const double dlogit = dalpha * a * (1.0 - a);
      const double drho = h * t * a * c;
      const double dcos = c > 0.0 ? h * t * a * rho : 0.0;
      Eigen::Vector3d dgradient = Eigen::Vector3d::Zero();
      if (dcos != 0.0) {
        const double norm = s.gradient.norm();
        const Eigen::Vector3d unit = s.gradient / norm;
        dgradient = dcos * (d - c * unit) / norm;
        dloss_ddirection += dcos * unit;
      }
      const VoxelStencil& st = s.stencil;
      Eigen::Vector3d dpoint = Eigen::Vector3d::Zero();
      for (int corner = 0; corner < 8; ++corner) {
        const auto cu = static_cast<std::size_t>(corner);
        const int at = VoxelStencil::cornerPatch(corner);
        const double w = st.weight[cu];
        const std::int64_t index = st.index[static_cast<std::size_t>(at)];
        if (index >= 0) {
          out.logits[static_cast<std::size_t>(index)] += dlogit * w;
          out.reflectance[static_cast<std::size_t>(index)] += drho * w;
        }
        const Eigen::Vector3d corner_gradient = st.cornerGradient(corner, size_);
        for (int axis = 0; axis < 3; ++axis) {
          const int step = axis == 0 ? 1 : (axis == 1 ? 4 : 16);
          const double dl = w * dgradient[axis] * half_over_size_;
          const std::int64_t up = st.index[static_cast<std::size_t>(at + step)];
          const std::int64_t down = st.index[static_cast<std::size_t>(at - step)];
          if (up >= 0) {
            out.logits[static_cast<std::size_t>(up)] += dl;
          }
          if (down >= 0) {
            out.logits[static_cast<std::size_t>(down)] -= dl;
          }
        }
        const double dweight = dlogit * st.logit[static_cast<std::size_t>(at)] +
                               drho * st.reflectance[cu] + dgradient.dot(corner_gradient);
        dpoint += dweight * st.d_weight[cu];
      }
      // p_world = t + R p_sonar, perturbed as R (p_sonar + omega x p_sonar + v).
      const Eigen::Vector3d dpoint_sonar = Rt_ * dpoint;
      out.twist.head<3>() += dpoint_sonar;
      out.twist.tail<3>() += s.p_sonar.cross(dpoint_sonar);
    }
    out.twist.tail<3>() += ray.direction_sonar.cross(Rt_ * dloss_ddirection);
    // I = G s p(theta) cos(theta) * sum_i w_i (+ B): through p, the knots; through G, the gain.
    const double dpower = ray.scale * std::cos(ray.elevation_rad) * upstream_sum;
    const ProfileWeights pw = profile_.weights(ray.elevation_rad);
    for (std::size_t m = 0; m < 4; ++m) {
      out.knots_db[static_cast<std::size_t>(pw.knot[m])] +=
          dpower * ray.power * kDbToPower * pw.weight[m];
    }
    out.gain += ray.unit_scale * ray.beam_weight * upstream_sum;
  }

  /// The sums, and the background's: over the traced beams' columns only (the others are no
  /// part of the model's prediction, so none of its gradient).
  ModelGradient total(int beam_stride, int beam_offset) const {
    ModelGradient sum(per_slot_.front()->logits.size(), per_slot_.front()->knots_db.size(),
                      per_slot_.front()->background.size());
    for (const auto& slot : per_slot_) {
      sum.add(*slot);
    }
    for (int row = 0; row < dloss_.rows; ++row) {
      const auto* dloss = dloss_.ptr<double>(row);
      double traced = 0.0;
      for (int col = beam_offset; col < dloss_.cols; col += beam_stride) {
        traced += dloss[col];
      }
      sum.background[static_cast<std::size_t>(row)] = traced;
    }
    return sum;
  }

 private:
  static constexpr double kDbToPower = std::numbers::ln10 / 10.0;
  const ElevationProfile& profile_;
  const RangeBins& bins_;
  Eigen::Matrix3d Rt_;
  double size_;
  double half_over_size_;
  const cv::Mat& dloss_;
  cv::Mat dloss_columns_;
  std::vector<std::unique_ptr<ModelGradient>> per_slot_;
};

void checkLossGradient(const SonarModel& sonar, const cv::Mat& dloss_dframe) {
  if (dloss_dframe.type() != CV_64F || dloss_dframe.rows != sonar.rows() ||
      dloss_dframe.cols != sonar.cols()) {
    throw Error("forward model", "loss gradient", "expected a CV_64F image of the frame's size");
  }
}

}  // namespace

std::size_t FrameTrace::samples() const {
  std::size_t n = 0;
  for (const Beam& beam : beams_) {
    n += beam.samples.size();
  }
  return n;
}

template <typename RayBody>
void ForwardModel::forEachTracedRay(const FrameTrace& trace, const RayBody& body) const {
  Slots slots(pool_.size());
  pool_.parallelFor(trace.beams_.size(), 4, [&](std::size_t begin, std::size_t end) {
    const unsigned slot = slots.take();
    for (auto n = begin; n < end; ++n) {
      const FrameTrace::Beam& beam = trace.beams_[n];
      for (std::size_t r = 0; r < beam.rays.size(); ++r) {
        body(beam.rays[r], beam.of(r), slot);
      }
    }
    slots.give(slot);
  });
}

template <typename Sample>
void ForwardModel::deposit(const ModelRay& ray, std::span<const Sample> samples,
                           cv::Mat& columns) const {
  auto* column = columns.ptr<double>(ray.beam);
  for (const SampleValues& s : samples) {
    const double energy =
        lambertianReturn(ray.scale, s.reflectance, s.cos_incidence, ray.beam_weight) *
        (s.transmittance * s.alpha);
    depositAtRange(s.range_m, energy, sonar_.range(), column);
  }
}

cv::Mat ForwardModel::predict(const BlockGrid& grid, const FrameView& view) const {
  cv::Mat columns(sonar_.cols(), sonar_.rows(), CV_64F, cv::Scalar(0.0));
  forEachRay(grid, view, [&](const ModelRay& ray, std::span<const RaySample> samples, unsigned) {
    deposit<RaySample>(ray, samples, columns);
  });
  return backgroundAdded(columns, view.background);
}

ModelGradient ForwardModel::gradient(const BlockGrid& grid, const FrameView& view,
                                     const cv::Mat& dloss_dframe) const {
  checkLossGradient(sonar_, dloss_dframe);
  GradientSums sums(grid, view, sonar_.range(), dloss_dframe, pool_.size());
  forEachRay(grid, view,
             [&](const ModelRay& ray, std::span<const RaySample> samples, unsigned slot) {
               sums.add(ray, samples, slot);
             });
  return sums.total(settings_.beam_stride, settings_.beam_offset);
}

void ForwardModel::trace(const BlockGrid& grid, const FrameView& view, FrameTrace& trace) const {
  const int stride = settings_.beam_stride;
  const int first = settings_.beam_offset;
  const int traced = tracedBeams();
  trace.beams_.resize(static_cast<std::size_t>(traced));
  for (FrameTrace::Beam& beam : trace.beams_) {
    beam.rays.clear();
    beam.ends.clear();
    beam.samples.clear();
  }
  trace.origin_ = view.T_world_sonar.translation();
  forEachRay(grid, view, [&](const ModelRay& ray, std::span<const RaySample> samples, unsigned) {
    FrameTrace::Beam& beam = trace.beams_[static_cast<std::size_t>((ray.beam - first) / stride)];
    beam.rays.push_back(ray);
    for (const RaySample& sample : samples) {
      beam.samples.push_back(sample);  // its values
    }
    beam.ends.push_back(beam.samples.size());
  });
}

cv::Mat ForwardModel::predict(const FrameTrace& trace, const FrameView& view) const {
  cv::Mat columns(sonar_.cols(), sonar_.rows(), CV_64F, cv::Scalar(0.0));
  forEachTracedRay(trace, [&](const ModelRay& ray, std::span<const SampleValues> samples,
                              unsigned) { deposit(ray, samples, columns); });
  return backgroundAdded(columns, view.background);
}

ModelGradient ForwardModel::gradient(const FrameTrace& trace, const BlockGrid& grid,
                                     const FrameView& view, const cv::Mat& dloss_dframe) const {
  checkLossGradient(sonar_, dloss_dframe);
  GradientSums sums(grid, view, sonar_.range(), dloss_dframe, pool_.size());
  // The voxels each sample read, read again at the point the march took it.
  std::vector<std::unique_ptr<StencilReader>> readers;
  std::vector<std::vector<RaySample>> read(pool_.size());
  for (unsigned s = 0; s < pool_.size(); ++s) {
    readers.push_back(std::make_unique<StencilReader>(grid));
  }
  forEachTracedRay(
      trace, [&](const ModelRay& ray, std::span<const SampleValues> values, unsigned slot) {
        std::vector<RaySample>& samples = read[slot];
        samples.resize(values.size());
        for (std::size_t i = 0; i < values.size(); ++i) {
          static_cast<SampleValues&>(samples[i]) = values[i];
          const Eigen::Vector3d p = trace.origin_ + values[i].range_m * ray.direction_world;
          readers[slot]->readCorners(p, samples[i].stencil);
          readers[slot]->readPatch(samples[i].stencil);
        }
        sums.add(ray, samples, slot);
      });
  return sums.total(settings_.beam_stride, settings_.beam_offset);
}

}  // namespace sonarcarve
