#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/Quat.h"
#include "core/ShapeKind.h"
#include "core/Vec3.h"

namespace tabletop {

/// A shape's size and what follows from it, without Bullet: the one home of
/// shape geometry that physics, the rules, drawing and the checks read.
/// Local frame: origin at the centre of mass, +Y up, principal axes.
/// Sizes in metres, as a scenario gives them: a cube's side, a sphere's
/// radius, a box's width, height and depth (X, Y, Z), a cylinder's base
/// radius, top radius and height (a truncated cone when they differ).
class ShapeGeometry {
 public:
  static ShapeGeometry cube(double side);
  static ShapeGeometry sphere(double radius);
  static ShapeGeometry box(double width, double height, double depth);
  static ShapeGeometry cylinder(double baseRadius, double topRadius, double height);
  /// From a scenario's "size" numbers (1 for a cube or a sphere, 3 for a
  /// box or a cylinder); nothing when the count is wrong.
  static std::optional<ShapeGeometry> fromSizes(ShapeKind kind, const std::vector<double>& sizes);

  ShapeKind kind() const { return kind_; }
  /// The scenario's "size" numbers again.
  std::vector<double> sizes() const;

  /// Half extents of the local bounding box.
  Vec3 halfExtents() const;
  /// Distances from the centre of mass down to the lowest and up to the
  /// highest point.
  double below() const;
  double above() const;
  /// How far the lowest point lies below the centre of mass once the body
  /// is turned by `q` (body to world, +Y up): a box's corner, a sphere's
  /// radius, the lowest point of a frustum's rims or a cone's point.
  double below(const Quat& q) const;
  /// Height of a cylinder's centre of mass above its base (a frustum's
  /// centroid); half the height for the other shapes.
  double centroidHeight() const;
  /// Volume, m^3.
  double volume() const;
  /// Principal moments of inertia about the centre of mass for `mass` kg
  /// spread uniformly, kg m^2 (closed forms; a frustum's by integrals over
  /// its height).
  Vec3 inertia(double mass) const;
  /// An upper bound on the distance from the centre of mass to the
  /// farthest point (exact but for a cone, for which the larger radius and
  /// the farther end are taken together).
  double boundingRadius() const;
  /// Half the smallest dimension (a cylinder's smaller radius or half its
  /// height), metres.
  double smallestHalfDimension() const;
  /// Half the footprint of the top face along world X and Z when turned by
  /// `yawDegrees`: the square bounding a turned box; a round top's radius
  /// both ways.
  std::pair<double, double> topFootprint(double yawDegrees) const;
  /// Whether the top is round (sphere, cylinder).
  bool round() const { return kind_ == ShapeKind::Sphere || kind_ == ShapeKind::Cylinder; }

  double side() const { return a_; }         ///< cube
  double radius() const { return a_; }       ///< sphere; a cylinder's base
  double topRadius() const { return b_; }    ///< cylinder
  double height() const { return c_; }       ///< cylinder; a box's Y size is b()
  double width() const { return a_; }        ///< box X
  double boxHeight() const { return b_; }    ///< box Y
  double depth() const { return c_; }        ///< box Z

 private:
  ShapeGeometry(ShapeKind kind, double a, double b, double c) : kind_(kind), a_(a), b_(b), c_(c) {}
  ShapeKind kind_;
  double a_, b_, c_;
};

}  // namespace tabletop
