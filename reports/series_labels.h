#pragma once
/// \file series_labels.h
/// \brief Labels that tell fit series (and crossover groups) apart. A label names the physics
/// that usually distinguishes series (dimension, model, stiffness, lambda and its parts); when
/// two labels still coincide, the parameters in which their jobs differ are appended, named as
/// in the parameter table (engine/parameters.cpp) and in its order, so that a new parameter
/// needs no code here to show up (e.g. "reinjection.rule=lanes").
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace beverloo {

/// labels[i] describes jobs[i] (a canonical job without its per-point fields). Appends
/// " path=value" to colliding labels for every path whose value differs within the collision.
void disambiguate_labels(std::vector<std::string>& labels, const std::vector<nlohmann::json>& jobs);

}  // namespace beverloo
