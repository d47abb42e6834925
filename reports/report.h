#pragma once
/// \file report.h
/// \brief `beverloo report`: fits the campaign, stores the fits, and renders with gnuplot every
/// figure the data supports (SVG + PNG, each beside its data file and gnuplot script so that a
/// user can restyle it), the fit tables (CSV, Markdown) and an index.html that gathers them.
#include <string>
#include <vector>

#include "orchestrator/campaign/campaign_scope.h"

namespace beverloo {

struct ReportFigure {
  std::string name, title;
  bool made = false;
  std::string why_not;  ///< when not made: what data it needs
};

/// Writes the report of the campaigns of `scope` (by default the latest) in campaign_dir into
/// out_dir; returns the figures. Throws on I/O errors and on a scope naming no campaign there
/// (ConfigError, before anything is written); missing data only leaves figures out (with the
/// reason in index.html).
std::vector<ReportFigure> write_report(const std::string& campaign_dir, const std::string& out_dir,
                                       const CampaignScope& scope = CampaignScope::latest());

}  // namespace beverloo
