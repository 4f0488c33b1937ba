// Coulomb friction: the threshold is the coefficient times the contact
// pressure, g = F l1 (doc/theory.md §1). It depends on the unknown pressure,
// so the threshold iteration runs around the Uzawa iteration.
#include <dualcontact/friction_law.h>

namespace dualcontact
{
  using namespace dealii;

  namespace
  {
    class Coulomb : public FrictionLaw
    {
    public:
      std::string
      name() const override
      {
        return "coulomb";
      }

      std::string
      description() const override
      {
        return "Coulomb: the threshold iteration g = F l1 around Uzawa on "
               "l1, l2";
      }

      std::string
      help() const override
      {
        return "|sigma_t| <= F |sigma_n| with the coefficient "
               "<Friction/Coefficient>";
      }

      void
      declare_parameters(EntryDeclarer &declarer) const override
      {
        declarer.enter_subsection("Friction");
        declarer.declare_entry("Coefficient",
                               "0",
                               EntryPattern::text(),
                               "Coulomb friction coefficient F [-], >= 0: a "
                               "number or an expression in x, y (z).");
        declarer.leave_subsection();
      }

      bool
      depends_on_pressure() const override
      {
        return true;
      }

      std::string
      parameter_entry() const override
      {
        return "Coefficient";
      }

      double
      threshold(const double F, const double l1) const override
      {
        return F * l1;
      }

      // F N if the normal load N is known: then the tangential contact
      // force is at most sum_s m_s F_s l1_s <= F_max N.
      double
      capacity(const double,
               const double largest_F,
               const double normal_load,
               std::string &why) const override
      {
        if (normal_load < 0.)
          return -1.;
        why = "F N, N = " + std::to_string(normal_load) + " the normal load";
        return largest_F * normal_load;
      }
    };

    const bool registered = register_friction_law("coulomb", [] {
      return std::make_unique<Coulomb>();
    });
  } // namespace
} // namespace dualcontact
