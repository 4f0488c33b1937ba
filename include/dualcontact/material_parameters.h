// <Material>: the elastic constants of the bodies. Its own header, so that
// what needs only the material (an obstacle's expressions, the cell
// assembly) does not include every subsection; the entries are declared,
// parsed and checked in source/parameters/material.cc.
#ifndef dualcontact_material_parameters_h
#define dualcontact_material_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <dualcontact/entry_declaration.h>

#include <map>
#include <utility>

namespace dualcontact
{
  using dealii::ParameterHandler;

  /** Isotropic linear elasticity; plane strain in 2D. */
  struct MaterialParameters
  {
    double youngs_modulus = 1.;
    double poissons_ratio = 0.3;
    // <Material/Materials by id>: the bodies of other materials, material
    // id -> (E, nu); the cells of every other id take the two above
    std::map<dealii::types::material_id, std::pair<double, double>> by_id;

    double
    lambda() const;
    double
    mu() const;
    /** The P-wave modulus lambda + 2 mu. */
    double
    p_wave_modulus() const
    {
      return lambda() + 2. * mu();
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
     * The stiffest of the materials (the largest P-wave modulus): the
     * contact solver scales its augmentation with it.
     */
    MaterialParameters
    stiffest() const
    {
      MaterialParameters result = of(dealii::numbers::invalid_material_id);
      for (const auto &[id, values] : by_id)
        if (of(id).p_wave_modulus() > result.p_wave_modulus())
          result = of(id);
      return result;
    }

    static void
    declare_parameters(EntryDeclarer &declarer);
    void
    parse_parameters(ParameterHandler &prm);
    /** E within the magnitudes the solver represents (exit 5). */
    void
    check_magnitudes() const;
  };
} // namespace dualcontact

#endif
