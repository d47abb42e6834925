#include "report.h"

#include <filesystem>

#include "core/atomic_file.h"
#include "orchestrator/campaign/campaign_dir.h"
#include "reports/campaign_fits.h"
#include "reports/figures/figure.h"
#include "reports/index_html.h"
#include "reports/paper_claims.h"

namespace beverloo {
namespace fs = std::filesystem;

std::vector<ReportFigure> write_report(const std::string& campaign_dir, const std::string& out_dir, const CampaignScope& scope) {
  // the fits are written into the database: one writer
  CampaignWriter writer(campaign_dir, CampaignWriter::Open::MustExist);
  db::Database& db = writer.db();
  scope.check_exists(db, "--campaign");
  const fs::path dir(out_dir);
  fs::create_directories(dir);
  const CampaignFits fits = fit_campaign(db, FlowRate::Q, scope);
  store_fits(db, fits);
  write_fit_tables(fits, out_dir);
  const std::vector<ClaimCheck> claims = check_paper_claims(fits);
  write_text_atomically((dir / "paper_claims.md").string(), claims_markdown(claims));
  write_text_atomically((dir / "paper_claims.csv").string(), claims_csv(claims));
  const figures::FigureContext context{fits, db, dir, scope};
  std::vector<ReportFigure> made;
  for (const figures::FigureMaker make : figures::report_figures()) made.push_back(make(context));
  write_text_atomically((dir / "index.html").string(), index_html(db, fits, made, scope));
  return made;
}

}  // namespace beverloo
