#include "dp_model.h"
#include "hopper_model.h"
#include "sp_model.h"

namespace beverloo {

template <int D>
std::unique_ptr<HopperModel<D>> make_model(const SimConfig& c, const Hopper<D>& hopper) {
  if constexpr (D == 2) {
    if (c.is_dp()) return std::make_unique<DpModel>(c, hopper);
  }
  // (config validation refuses DP in 3D)
  return std::make_unique<SpModel<D>>(c, hopper);
}

template std::unique_ptr<HopperModel<2>> make_model(const SimConfig&, const Hopper<2>&);
template std::unique_ptr<HopperModel<3>> make_model(const SimConfig&, const Hopper<3>&);

}  // namespace beverloo
