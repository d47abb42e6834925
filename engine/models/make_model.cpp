#include "dp_model.h"
#include "hopper_model.h"
#include "model_time_step.h"
#include "sp_model.h"

namespace beverloo {

// The one place that maps a configuration to its model: a new model adds a case to both.

template <int D>
std::unique_ptr<HopperModel<D>> make_model(const SimConfig& c, const Hopper<D>& hopper) {
  if constexpr (D == 2) {
    if (c.is_dp()) return std::make_unique<DpModel>(c, hopper);
  }
  // (config validation refuses DP in 3D)
  return std::make_unique<SpModel<D>>(c, hopper);
}

TimeScales model_time_scales(const SimConfig& c) {
  if (c.is_dp()) return DpModel::time_scales(c);
  return c.dimension == 3 ? SpModel<3>::time_scales(c) : SpModel<2>::time_scales(c);
}

template std::unique_ptr<HopperModel<2>> make_model(const SimConfig&, const Hopper<2>&);
template std::unique_ptr<HopperModel<3>> make_model(const SimConfig&, const Hopper<3>&);

}  // namespace beverloo
