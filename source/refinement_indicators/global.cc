// 'global' refinement: every cell is refined, h halves per cycle, as in
// the source method; no indicator.
#include <dualcontact/refinement_indicator.h>

namespace dualcontact
{
  namespace
  {
    const bool registered = register_refinement_indicator(
      "global",
      {"halves h everywhere, as the source method does.", nullptr, {}, {}, {}});
  } // namespace
} // namespace dualcontact
