#pragma once
// Conversions between GLM vectors and Bullet's btVector3, for the backend's sources (not
// installed). Bullet's btScalar is float or double (bullet-float64); every conversion is one
// static_cast per component.

#include <foresight/config.h>

#include <LinearMath/btVector3.h>

#include <glm/vec3.hpp>

FORESIGHT_NAMESPACE_BEGIN
namespace bullet_detail {

/// Any GLM 3-vector (float or double) as a btVector3.
template <class T>
btVector3 toBt(const glm::vec<3, T, glm::defaultp>& v) {
    return btVector3(static_cast<btScalar>(v.x), static_cast<btScalar>(v.y), static_cast<btScalar>(v.z));
}

/// A btVector3 as double.
inline glm::dvec3 toD(const btVector3& v) {
    return glm::dvec3(static_cast<double>(v.x()), static_cast<double>(v.y()), static_cast<double>(v.z()));
}

}  // namespace bullet_detail
FORESIGHT_NAMESPACE_END
