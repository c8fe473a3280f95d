#include "physics/shapes/PaddedShape.h"

// The table's children are built here alone: building btBoxShape's
// virtual functions, GCC's flow analysis warns that btBoxShape::getPlane
// (Bullet's header) may read an unset btVector4, a false alarm in Bullet's
// code that a pragma cannot reach, so CMakeLists.txt turns that one
// warning off for this file.

namespace tabletop {

template class PaddedShape<btBoxShape>;
template class PaddedShape<btCylinderShape>;

}  // namespace tabletop
