// the README's example, built against the installed package; exits 0 when it answers right
#include <convexloc/locate2d.hpp>

#include <vector>

int main() {
  convexloc::ConvexPolygon square(std::vector<convexloc::Vec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  convexloc::PolarLocator polar(square);
  bool ok = polar.locate({0.5, 1.0}) == convexloc::Location::Boundary &&
            polar.locate({0.5, 0.5}) == convexloc::Location::Inside &&
            polar.locate({2.0, 0.5}) == convexloc::Location::Outside;
  return ok ? 0 : 1;
}
