// The registry of normal laws: one row per law (contact_laws.h says what a law is).
#include "contact_laws.h"

#include "core/errors.h"
#include "harmonic_overlap.h"
#include "hertz_normal.h"
#include "sp_contact.h"

namespace beverloo {
namespace {

template <class Law>
NormalLawRow row(std::string_view name, std::string_view reads, std::string_view doc,
                 double (*energy_scale)(double E_sp, double sigma_mn)) {
  return {name,
          reads,
          doc,
          energy_scale,
          &Law::stiffness,
          &Law::force,
          Law::kLanes,
          &SpContactLoops<2>::template of<Law>,
          &SpContactLoops<3>::template of<Law>};
}

double E_sp_itself(double E_sp, double) { return E_sp; }
double E_sp_times_sigma(double E_sp, double sigma_mn) { return E_sp * sigma_mn; }

}  // namespace

const std::vector<NormalLawRow>& normal_laws() {
  static const std::vector<NormalLawRow> rows = {
      row<HarmonicOverlap>("energy", "E_sp", "U = (E_sp/2)(1 - r/sigma_mn)^2, every pair the energy scale E_sp (the paper's text)",
                           E_sp_itself),
      row<HarmonicOverlap>("force", "E_sp",
                           "U = (E_sp sigma_mn/2)(1 - r/sigma_mn)^2, a constant force scale E_sp (the authors' code)",
                           E_sp_times_sigma),
      row<HertzNormal>("hertz", "E_sp",
                       "U = (2/5) E_sp (1 - r/sigma_mn)^(5/2), a Hertzian force E_sp ov^(3/2)/sigma_mn (not in the paper; 2D: the "
                       "3D law on discs)",
                       E_sp_itself),
  };
  return rows;
}

const NormalLawRow& normal_law(std::string_view name) {
  for (const NormalLawRow& r : normal_laws())
    if (r.name == name) return r;
  std::string message = "\"";
  message.append(name).append("\": must be one of ").append(normal_law_names());
  throw ConfigError("sp_contact_law", message);
}

const std::string& normal_law_names() {
  static const std::string names = [] {
    std::string s;
    for (const NormalLawRow& r : normal_laws()) {
      if (!s.empty()) s += ',';
      s.append(r.name);
    }
    return s;
  }();
  return names;
}

const std::string& normal_law_docs() {
  static const std::string docs = [] {
    std::string s;
    for (const NormalLawRow& r : normal_laws()) {
      if (!s.empty()) s += "; ";
      s.append("\"").append(r.name).append("\": ").append(r.doc);
    }
    return s;
  }();
  return docs;
}

}  // namespace beverloo
