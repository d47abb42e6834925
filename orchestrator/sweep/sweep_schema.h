#pragma once
/// \file sweep_schema.h
/// \brief The parameter part of schema/sweep.schema.json, generated from the parameter table
/// (engine/parameters): the job object, its run and dp objects and the sweepable names. The
/// committed schema must hold exactly these definitions (a unit test compares them);
/// `beverloo params --schema-defs` prints them.
#include <nlohmann/json.hpp>

namespace beverloo {

/// {"job": ..., "run": ..., "topParameter": ..., "parameter": ...}: the $defs entries.
nlohmann::json parameter_schema_defs();

}  // namespace beverloo
