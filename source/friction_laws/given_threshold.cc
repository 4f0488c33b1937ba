// Given friction (Tresca): the threshold g is a datum of the scene,
// independent of the contact pressure, |l2| <= g.
#include <dualcontact/friction_law.h>

namespace dualcontact
{
  using namespace dealii;

  namespace
  {
    class GivenThreshold : public FrictionLaw
    {
    public:
      std::string
      name() const override
      {
        return "given";
      }

      std::string
      description() const override
      {
        return "given threshold (Tresca): Uzawa on l1 and l2";
      }

      std::string
      help() const override
      {
        return "Tresca, |sigma_t| <= g with the threshold "
               "<Friction/Threshold>";
      }

      void
      declare_parameters(EntryDeclarer &declarer) const override
      {
        declarer.enter_subsection("Friction");
        declarer.declare_entry("Threshold",
                               "0",
                               EntryPattern::text(),
                               "Given friction threshold g [stress], >= 0: a "
                               "number or an expression in x, y (z).");
        declarer.leave_subsection();
      }

      bool
      depends_on_pressure() const override
      {
        return false;
      }

      std::string
      parameter_entry() const override
      {
        return "Threshold";
      }

      double
      threshold(const double g, const double) const override
      {
        return g;
      }

      double
      capacity(const double weighted_sum,
               const double,
               const double,
               std::string &why) const override
      {
        why = "the sum of the given threshold over Gamma_C";
        return weighted_sum;
      }
    };

    const bool registered = register_friction_law("given", [] {
      return std::make_unique<GivenThreshold>();
    });
  } // namespace
} // namespace dualcontact
