#include <collide2d/kernels.h>

namespace collide2d {

// A face of A and a face of B trade kinds (1 and 2, the same two bits flipped); two corners trade
// places; a curved point has no features.
std::uint32_t swapped_feature(std::uint32_t id) {
  switch (feature_kind(id)) {
    case FeatureKind::face_of_a:
    case FeatureKind::face_of_b:
      return id ^ 3u << 16;
    case FeatureKind::corner_corner:
      return (id & 0xffff0000u) | (id & 0xffu) << 8 | (id >> 8 & 0xffu);
    case FeatureKind::curved:
      break;
  }
  return id;
}

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
