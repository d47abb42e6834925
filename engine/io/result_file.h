#pragma once
/// \file result_file.h
/// \brief result.h5, the per-job result (layout in docs/hdf5-layout.md). Written atomically.
#include <string>

#include "../config.h"
#include "../protocol/run_result.h"

namespace beverloo {

void write_result_file(const std::string& path, const SimConfig& c, const RunResult& r);

}  // namespace beverloo
