// What every tutorial program needs besides the step's own idea: aligned
// numbers, the self-checks, a reader for the CSV files the library writes
// (csv_table.h, included here),
// Hertz's closed form for the scene the program was given, and a main()
// that takes a parameter file and --set overrides and ends any error with
// one message and a non-zero exit status.
//
// The steps include it as "../common/tutorial_tools.h"; it is header-only,
// so a step stays one program that builds with the library alone.
#ifndef dualcontact_tutorial_tools_h
#define dualcontact_tutorial_tools_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>

#include <dualcontact/input_error.h>
#include <dualcontact/parameters.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "csv_table.h"

namespace dualcontact
{
  namespace tutorial
  {
    /** A number in printf format, for aligned screen lines. */
    inline std::string
    format(const char *pattern, const double x)
    {
      char buffer[64];
      std::snprintf(buffer, sizeof(buffer), pattern, x);
      return buffer;
    }

    /** Thrown when a program's own check fails: main() prints its text. */
    class CheckFailed : public std::runtime_error
    {
    public:
      using std::runtime_error::runtime_error;
    };

    /**
     * The checks of a step: what its README claims, tested on the step's
     * own numbers. Each check prints one line on rank 0, "passed" or
     * "FAILED", so that a failing run still shows all of them. The step's
     * run() returns its Checks, and run_tutorial() calls conclude() once
     * the step's objects are gone: a failed check is then one message and
     * exit status 1. The numbers are the same on all ranks, so all ranks
     * agree.
     */
    class Checks
    {
    public:
      Checks()
          : pcout(std::cout,
                  dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {}

      void
      operator()(const bool ok, const std::string &what)
      {
        pcout << (ok ? "  passed: " : "  FAILED: ") << what << "\n";
        ++n_checks;
        if (!ok)
          failed.push_back(what);
      }

      /** Throws CheckFailed naming the failed checks, if any failed. */
      void
      conclude() const
      {
        if (failed.empty())
          return;
        std::string text = std::to_string(failed.size()) + " of " +
                           std::to_string(n_checks) + " checks failed: ";
        for (unsigned int i = 0; i < failed.size(); ++i)
          text += (i > 0 ? "; " : "") + failed[i];
        throw CheckFailed(text);
      }

    private:
      dealii::ConditionalOStream pcout;
      unsigned int               n_checks = 0;
      std::vector<std::string>   failed;
    };

    /**
     * Hertz's frictionless contact of a curved elastic body (or a curved
     * rigid obstacle on an elastic half space) under the load P, with the
     * material of the scene and the radius R of its curved part: the body's
     * own radius for the built-in half disc or ball, otherwise the
     * obstacle's <Obstacle/Radius>. E* = E / (1 - nu^2).
     *
     * 2D, plane strain, a cylinder pressed along its length (P per unit
     * length):   a = sqrt(4 P R / (pi E*)),     p0 = 2 P / (pi a);
     * 3D, a ball: a = (3 P R / (4 E*))^(1/3),   p0 = 3 P / (2 pi a^2);
     * in both, p(r) = p0 sqrt(1 - r^2 / a^2) on |r| < a.
     * The stresses on the axis below the 2D contact (McEwen) are given at
     * the depth z: sigma_yy = -p0 a / s, sigma_xx = -p0 ((a^2 + 2 z^2)/(a s)
     * - 2 z / a), s = sqrt(a^2 + z^2).
     */
    struct Hertz
    {
      unsigned int dim;
      double       P, R, E_star, a, p0;

      Hertz(const Parameters &parameters, const double P)
          : dim(parameters.geometry.dimension)
          , P(P)
          , R(radius_of(parameters))
      {
        const double nu = parameters.material.poissons_ratio;
        E_star          = parameters.material.youngs_modulus / (1. - nu * nu);
        if (dim == 2)
          {
            a  = std::sqrt(4. * P * R / (dealii::numbers::PI * E_star));
            p0 = 2. * P / (dealii::numbers::PI * a);
          }
        else
          {
            a  = std::cbrt(3. * P * R / (4. * E_star));
            p0 = 3. * P / (2. * dealii::numbers::PI * a * a);
          }
      }

      double
      pressure(const double r) const
      {
        return p0 * std::sqrt(std::max(0., 1. - r * r / (a * a)));
      }

      double
      sigma_yy(const double z) const
      {
        return -p0 * a / std::sqrt(a * a + z * z);
      }

      double
      sigma_xx(const double z) const
      {
        const double s = std::sqrt(a * a + z * z);
        return -p0 * ((a * a + 2. * z * z) / (a * s) - 2. * z / a);
      }

      /** R from the scene, as the class comment says. */
      static double
      radius_of(const Parameters &parameters)
      {
        const std::string type = parameters.geometry.type;
        if (type == "half disc" || type == "quarter disc")
          return parameters.geometry.radius;
        const auto radius = parameters.obstacle.values.find("Obstacle/Radius");
        if (radius != parameters.obstacle.values.end() &&
            parameters.obstacle.type != "plane")
          return std::stod(radius->second);
        throw std::runtime_error(
          "Hertz needs a curved body (Geometry/Type = half disc or quarter "
          "disc) or a curved obstacle (<Obstacle/Radius>)");
      }
    };

    /**
     * A step's own requirement on its scene (2D only, frictionless...):
     * InputError with exit status 6 (entries that contradict each other)
     * and `message` unless `ok`.
     */
    inline void
    require(const bool ok, const std::string &message)
    {
      if (!ok)
        throw InputError(message, exit_inconsistent);
    }

    /**
     * The main() of a tutorial program: MPI, the parameter file (the
     * first argument that is not an option, `default_file` without one),
     * overrides after it as the dualcontact program takes them
     * (`--set "Material/Poisson's ratio=0.3"`), then `run(parameters)`,
     * and the conclusion of the checks it returns.
     * Any error ends in one message on rank 0, "<name>: ...", and an exit
     * status: a failed check 1, bad input its InputError code (as the
     * dualcontact program), anything else 1.
     */
    inline int
    run_tutorial(int                                        argc,
                 char                                     **argv,
                 const std::string                         &name,
                 const std::string                         &default_file,
                 const std::function<Checks(Parameters &)> &run)
    {
      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      const bool                               root =
        dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
      std::ostringstream message;
      int                status = 1;
      try
        {
          std::string              file = default_file;
          std::vector<std::string> overrides;
          for (int i = 1; i < argc; ++i)
            if (std::string(argv[i]) == "--set" && i + 1 < argc)
              overrides.emplace_back(argv[++i]);
            else
              file = argv[i];
          Parameters parameters;
          parameters.read_file(file, overrides);
          run(parameters).conclude();
          return 0;
        }
      catch (const CheckFailed &failure)
        {
          message << "check failed: " << failure.what();
        }
      catch (const InputError &error)
        {
          message << printable(error.what());
          status = error.code;
        }
      catch (const dealii::ExceptionBase &exc)
        {
          message << "error: ";
          exc.print_info(message);
        }
      catch (const std::exception &exc)
        {
          message << "error: " << exc.what();
        }
      if (root)
        std::cerr << name << ": " << message.str() << std::endl;
      return status;
    }
  } // namespace tutorial
} // namespace dualcontact

#endif
