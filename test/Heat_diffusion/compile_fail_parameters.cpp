// Must NOT compile: named parameters with a value of the wrong type. The CTest case
// compile_fail_parameters builds this file and checks that the compiler stops with
// one static_assert message per parameter, naming it, and nothing else.
#include <CGAL/Heat_diffusion/parameters.h>

namespace HD = CGAL::Heat_diffusion;

int main()
{
  // a count given as a floating-point number would be truncated to 2 steps
  const auto steps = HD::parameters::number_of_steps(2.7);
  // a string where a number is expected, in a chain of the package's members
  const auto time = HD::parameters::sigma(0.1).time("two");
  // a count after one of CGAL's parameters
  const auto levels = HD::parameters::vertex_point_map(0).steps_per_level(1.5);
  static_cast<void>(steps);
  static_cast<void>(time);
  static_cast<void>(levels);
  return 0;
}
