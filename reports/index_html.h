#pragma once
/// \file index_html.h
/// \brief The report's index.html: the run summary, the units, the fit tables (values rounded
/// to their errors, poorly determined fits flagged) and every figure of the list, made or not.
#include <string>
#include <vector>

#include "orchestrator/db/database.h"
#include "reports/campaign_fits.h"
#include "reports/report.h"

namespace beverloo {

std::string index_html(db::Database& db, const CampaignFits& fits, const std::vector<ReportFigure>& figures,
                       const CampaignScope& scope = CampaignScope::latest());

}  // namespace beverloo
