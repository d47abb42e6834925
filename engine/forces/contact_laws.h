#pragma once
/// \file contact_laws.h
/// \brief The seam for contact laws between particles (after LAMMPS GRANULAR's sub-models: a
/// law is a small type, a registry row and its tests).
///
/// A contact is a normal law (the repulsion of two touching particles) and a dissipation law
/// (kinetic friction with a normal and a tangential coefficient, kinetic_friction.h). A normal
/// law is a type with
///   - `static double force(double eps, double inv_sig, double r, double& energy, double& ov)`:
///     for a touching pair at distance r < sigma (a pair of particles, or a DP vertex and an
///     edge), the overlap ov = 1 - r/sigma, its energy added to energy, and the returned
///     repulsion |F| = -dU/dr >= 0;
///   - `static double stiffness(double eps, double sigma)`: the largest d^2U/dr^2 over every
///     overlap 0 < ov < 1, for dt "auto" (a pair closer than ov = 1 is a blow-up anyway);
///   - `static constexpr bool kLanes`: whether the pair runs have a SIMD lane form of it
///     (sp_pairs_sse2.h, sp_pairs_avx2.h). A law without one runs at scalar width: correct at
///     once, fast later.
/// Its registry row (contact_laws.cpp, `row<Law>(...)`) names it as the job file spells it
/// (`sp_contact_law`), says which parameters it reads and how the pair's energy scale eps
/// follows from E_sp and the pair's contact distance, and makes the pair loops of SpContact
/// for it (2D and 3D). parameters.cpp's allowed values and the models' time scales ask the
/// registry. Adding a law: one header in engine/forces/ and one row (docs/architecture.md).
#include <string>
#include <string_view>
#include <vector>

namespace beverloo {

template <int D>
struct SpContactLoops;  // sp_contact.h: the pair loops of one law

struct NormalLawRow {
  std::string_view name;   ///< as `sp_contact_law` spells it
  std::string_view reads;  ///< the job parameters it reads
  std::string_view doc;    ///< one line for docs/job-file.md
  /// The energy scale of a pair of contact distance sigma_mn (in sigma_avg), from E_sp.
  double (*energy_scale)(double E_sp, double sigma_mn);
  /// The largest d^2U/dr^2 of a pair of energy scale eps and contact distance sigma (dt "auto").
  double (*stiffness)(double eps, double sigma);
  /// The law's scalar pair (Law::force): the generic tests of every row use it.
  double (*force)(double eps, double inv_sig, double r, double& energy, double& ov);
  bool lanes;  ///< has a SIMD lane form
  const SpContactLoops<2>& (*loops2)();
  const SpContactLoops<3>& (*loops3)();
  template <int D>
  const SpContactLoops<D>& loops() const {
    if constexpr (D == 2) return loops2();
    else return loops3();
  }
};

/// Every normal law, in the order of docs/job-file.md.
const std::vector<NormalLawRow>& normal_laws();
/// The row of a law by its name; throws ConfigError("sp_contact_law", ...) for another name.
const NormalLawRow& normal_law(std::string_view name);
/// "energy,force,..." (parameters.cpp's allowed values).
const std::string& normal_law_names();
/// The laws' docs as one text (parameters.cpp's doc of sp_contact_law).
const std::string& normal_law_docs();

}  // namespace beverloo
