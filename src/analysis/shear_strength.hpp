// Shear strength of a direct shear curve (physics.md section 4; rapeseed paper section 2.2):
// the mean shear stress over the strength window of shear displacement,
//
//   tau_f = (1 / N) sum_{k : d_start <= d_k <= d_end} tau_k        (Pa)
//
// d_k the shear displacement (m) and tau_k the shear stress (Pa) of sample k; the window
// [d_start, d_end] is shear_box.strength_window_start/end (default 20-30 mm, the stationary
// part of the curve). One definition for both sides of a calibration: colza's shear box adds
// every time step (even displacement steps: the lower half moves at constant speed), a
// measured curve adds its rows (so it should be sampled at even displacement steps too).
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

}  // namespace colza
