// Affine transforms of Mitsuba scene files (doc/scene-format.md, "Mitsuba
// scenes"): 4x4 matrices for column vectors, composed in double precision.
#pragma once
#include "base/vec3.hpp"

namespace smallmlt {

struct Mat4 {
    double m[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};

    static Mat4 translate(double x, double y, double z);
    static Mat4 scale(double x, double y, double z);
    // Counter-clockwise by `degrees` about `axis` (not zero), right-handed.
    static Mat4 rotate(double ax, double ay, double az, double degrees);
    // Columns (left, up', dir, origin): local +z looks at `target`, +y is
    // `up` made perpendicular, +x = cross(up, dir). Returns false where up
    // is zero or parallel to the view.
    static bool look_at(Vec3 origin, Vec3 target, Vec3 up, Mat4& out);

    Vec3 point(Vec3 p) const;
    Vec3 vector(Vec3 v) const;
    // A normal: by the inverse transpose of the linear part (not unit).
    Vec3 normal(Vec3 n) const;
    // Determinant of the linear part.
    double det3() const;
    bool is_identity() const;
};

// a * b: b applied first.
Mat4 operator*(const Mat4& a, const Mat4& b);

} // namespace smallmlt
