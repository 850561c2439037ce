// Shear strength of a direct shear curve (physics.md section 4; rapeseed paper section 2.2):
// the mean shear stress over the strength window of shear displacement,
//
//   tau_f = (1 / N) sum_{k : d_start <= d_k <= d_end} tau_k        (Pa)
//
// d_k the shear displacement (m) and tau_k the shear stress (Pa) of sample k; the window
// [d_start, d_end] is shear_box.strength_window_start/end (default 20-30 mm, the stationary
// part of the curve). One definition for both sides of a calibration: colza's shear box adds
// every time step (displacement steps of v dt, the lower half moving at constant speed v;
// with the automatic time step dt varies by ~10 %, which moves the mean by ~1e-4 relative
// against a displacement-weighted mean), a measured curve adds its rows (so it should be
// sampled at even displacement steps).
#pragma once
#include <cstddef>
#include <vector>

namespace colza {

struct StrengthWindow {
  double start = 0.0;  // m
  double end = 0.0;    // m
  bool contains(double displacement) const { return displacement >= start && displacement <= end; }
};

// Running mean of the shear stress over the window; samples outside the window are ignored.
class ShearStrengthMean {
 public:
  explicit ShearStrengthMean(StrengthWindow window) : window_(window) {}
  void add(double displacement, double shear_stress) {
    if (!window_.contains(displacement)) return;
    sum_ += shear_stress;
    ++samples_;
  }
  std::size_t samples() const { return samples_; }
  double value() const { return samples_ ? sum_ / static_cast<double>(samples_) : 0.0; }  // Pa; 0 = no sample
  const StrengthWindow& window() const { return window_; }

 private:
  StrengthWindow window_;
  double sum_ = 0.0;
  std::size_t samples_ = 0;
};

// tau_f of a whole curve (displacement in m, shear stress in Pa, same length).
ShearStrengthMean shear_strength_of_curve(const std::vector<double>& displacement,
                                          const std::vector<double>& shear_stress, StrengthWindow window);

// Peak strength: the largest mean shear stress over a trailing interval of shear
// displacement of width w,
//
//   tau_peak = max_i (1 / N_i) sum_{k : d_i - w <= d_k <= d_i} tau_k        (Pa),
//
// over the rows i whose interval lies on the curve (d_i - w >= d_0). Averaging over w (say
// 1 mm) makes the peak a property of the curve, not of one noisy sample; one definition for
// a measured curve's rows and the simulation's recorded rows (every record_interval steps).
// Before the peak the bonds hold; the stationary window after it (above) sees few of them.
struct ShearPeak {
  double value = 0.0;         // Pa
  double displacement = 0.0;  // m, the end d_i of the interval with the largest mean
  std::size_t samples = 0;    // rows in that interval; 0 = the curve is shorter than w
};
ShearPeak peak_shear_strength(const std::vector<double>& displacement, const std::vector<double>& shear_stress,
                              double width);

}  // namespace colza
