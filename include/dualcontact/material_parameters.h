// <Material>: the elastic constants of the bodies. Its own header, so that
// what needs only the material (an obstacle's expressions, the cell
// assembly) does not include every subsection; the entries are declared,
// parsed and checked in source/parameters/material.cc.
#ifndef dualcontact_material_parameters_h
#define dualcontact_material_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <dualcontact/cell_kind.h>
#include <dualcontact/entry_declaration.h>

#include <map>
#include <string>
#include <utility>

namespace dualcontact
{
  using dealii::ParameterHandler;

  /**
   * How a body is discretised: in displacements alone, or in displacements
   * and the pressure p = -kappa div u (doc/mixed.md), which does not lock
   * as nu -> 1/2 and allows nu = 1/2.
   */
  enum class Formulation
  {
    displacement,
    mixed
  };

  /**
   * Why the mixed formulation does not take displacement degree `degree`
   * on cells of `kind`, in a sentence; empty where it does (Taylor-Hood
   * Q_k/Q_{k-1} and P_k/P_{k-1}, k >= 2). k = 1 would pair Q1 with Q0 or
   * P1 with P0, which fail the inf-sup condition (Q1/Q0 has checkerboard
   * pressure modes, P1/P0 locks).
   */
  std::string
  mixed_pair_refusal(CellKind kind, unsigned int degree);

  /** Isotropic linear elasticity; plane strain in 2D. */
  struct MaterialParameters
  {
    double      youngs_modulus = 1.;
    double      poissons_ratio = 0.3;
    Formulation formulation    = Formulation::displacement;
    // <Material/Materials by id>: the bodies of other materials, material
    // id -> (E, nu); the cells of every other id take the two above
    std::map<dealii::types::material_id, std::pair<double, double>> by_id;

    double
    lambda() const;
    double
    mu() const;
    /** 1/kappa = 3 (1 - 2 nu) / E, zero at nu = 1/2. */
    double
    inverse_bulk_modulus() const
    {
      return 3. * (1. - 2. * poissons_ratio) / youngs_modulus;
    }
    /**
     * The coefficient of div u div v in the displacement block, beside
     * 2 mu eps(u):eps(v): lambda, or -2 mu/3 in the mixed formulation,
     * whose displacement block is the deviatoric 2 mu dev eps(u):dev
     * eps(v) (dev in 3D, also in plane strain) and whose pressure carries
     * the rest of the stress: sigma = 2 mu eps + block_lambda() tr(eps) I
     * - p I.
     */
    double
    block_lambda() const
    {
      return formulation == Formulation::mixed ? -2. / 3. * mu() : lambda();
    }
    /**
     * The modulus the contact solver scales its augmentation with: the
     * P-wave modulus lambda + 2 mu, which follows the stiffness of a
     * displacement discretisation as it locks; in the mixed formulation,
     * which does not lock, 4 mu (E/(1 - nu^2) at nu = 1/2, the modulus of
     * an incompressible body's surface; 1.54 E at nu = 0.3 against the
     * P-wave modulus's 1.35 E).
     */
    double
    contact_modulus() const
    {
      return formulation == Formulation::mixed ? 4. * mu() :
                                                 lambda() + 2. * mu();
    }

    /** The material of the cells with material id `id`. */
    MaterialParameters
    of(const dealii::types::material_id id) const
    {
      MaterialParameters material;
      const auto         it = by_id.find(id);
      material.youngs_modulus =
        it == by_id.end() ? youngs_modulus : it->second.first;
      material.poissons_ratio =
        it == by_id.end() ? poissons_ratio : it->second.second;
      material.formulation = formulation;
      return material;
    }

    /**
     * Whether cells of material id `id` have a material: every id does
     * while <Material/Materials by id> is empty; once it lists some, the
     * ids listed and 0, which takes <Young's modulus> and <Poisson's ratio>.
     */
    bool
    has(const dealii::types::material_id id) const
    {
      return by_id.empty() || id == 0 || by_id.count(id) > 0;
    }

    /**
     * The stiffest of the materials (the largest contact_modulus()): the
     * contact solver scales its augmentation with it.
     */
    MaterialParameters
    stiffest() const
    {
      MaterialParameters result = of(dealii::numbers::invalid_material_id);
      for (const auto &[id, values] : by_id)
        if (of(id).contact_modulus() > result.contact_modulus())
          result = of(id);
      return result;
    }

    static void
    declare_parameters(EntryDeclarer &declarer);
    void
    parse_parameters(ParameterHandler &prm);
    /** nu = 1/2 needs the mixed formulation (InputError). */
    void
    check_incompressible(double nu, const std::string &entry) const;
    /** E within the magnitudes the solver represents (exit 5). */
    void
    check_magnitudes() const;
  };
} // namespace dualcontact

#endif
