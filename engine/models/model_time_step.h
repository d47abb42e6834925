#pragma once
/// \file model_time_step.h
/// \brief The time step of a configuration: the configured model's time scales
/// (SpModel::time_scales, DpModel::time_scales) through the common rule of
/// engine/integrate/time_step.h. Needs no model instance, so that a sweep or the CLI can refuse
/// an unstable explicit dt before anything is built or written.
#include "../config.h"
#include "../integrate/time_step.h"

namespace beverloo {

/// The time scales of c's model (dispatched in make_model.cpp, beside make_model).
TimeScales model_time_scales(const SimConfig& c);

/// Throws ConfigError("dt", ...) if an explicit dt is too large for the stiffest term.
inline TimeStepChoice choose_time_step(const SimConfig& c) { return choose_time_step(c.dt, model_time_scales(c)); }

}  // namespace beverloo
