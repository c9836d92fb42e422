#include <collide2d/kernels.h>

namespace collide2d {

// The points past the manifold's size are unset: only the manifold's own are turned round.
Contact Contact::swapped() const {
  Contact out = *this;
  out.normal = -normal;
  std::swap(out.point_a, out.point_b);
  for (int k = 0; k < manifold_size; ++k) {
    ContactPoint& p = out.manifold[k];
    std::swap(p.point_a, p.point_b);
    p.id = swapped_feature(p.id);
  }
  return out;
}

}  // namespace collide2d
