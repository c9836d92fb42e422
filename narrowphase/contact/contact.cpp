#include <collide2d/kernels.h>

namespace collide2d {

std::uint32_t swapped_feature(std::uint32_t id) {
  const int first = static_cast<int>(id >> 8 & 0xff), second = static_cast<int>(id & 0xff);
  switch (feature_kind(id)) {
    case FeatureKind::face_of_a:
      return feature_id(FeatureKind::face_of_b, first, second);
    case FeatureKind::face_of_b:
      return feature_id(FeatureKind::face_of_a, first, second);
    case FeatureKind::corner_corner:
      return feature_id(FeatureKind::corner_corner, second, first);
    case FeatureKind::curved:
      break;
  }
  return id;
}

Contact Contact::swapped() const {
  Contact out = *this;
  out.normal = -normal;
  std::swap(out.point_a, out.point_b);
  for (ContactPoint& p : out.manifold) {
    std::swap(p.point_a, p.point_b);
    p.id = swapped_feature(p.id);
  }
  return out;
}

}  // namespace collide2d
