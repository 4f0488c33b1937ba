// No friction: the contact pressure alone; no tangential multiplier.
#include <dualcontact/friction_law.h>

namespace dualcontact
{
  namespace
  {
    class Frictionless : public FrictionLaw
    {
    public:
      std::string
      name() const override
      {
        return "none";
      }

      std::string
      description() const override
      {
        return "no";
      }

      std::string
      help() const override
      {
        return "frictionless";
      }

      bool
      has_friction() const override
      {
        return false;
      }

      bool
      depends_on_pressure() const override
      {
        return false;
      }

      std::string
      parameter_entry() const override
      {
        return "";
      }

      double
      threshold(const double, const double) const override
      {
        return 0.;
      }

      double
      capacity(const double,
               const double,
               const double,
               std::string &why) const override
      {
        why = "frictionless contact";
        return 0.;
      }
    };

    const bool registered = register_friction_law("none", [] {
      return std::make_unique<Frictionless>();
    });
  } // namespace
} // namespace dualcontact
