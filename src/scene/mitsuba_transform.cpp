#include "scene/mitsuba_transform.hpp"

#include <cmath>

namespace smallmlt {

Mat4 Mat4::translate(double x, double y, double z) {
    Mat4 t;
    t.m[0][3] = x;
    t.m[1][3] = y;
    t.m[2][3] = z;
    return t;
}

Mat4 Mat4::scale(double x, double y, double z) {
    Mat4 t;
    t.m[0][0] = x;
    t.m[1][1] = y;
    t.m[2][2] = z;
    return t;
}

Mat4 Mat4::rotate(double ax, double ay, double az, double degrees) {
    const double len = std::sqrt(ax * ax + ay * ay + az * az);
    const double x = ax / len, y = ay / len, z = az / len;
    const double a = degrees * (M_PI / 180.0);
    const double c = std::cos(a), s = std::sin(a), t = 1 - c;
    Mat4 r;
    r.m[0][0] = t * x * x + c;
    r.m[0][1] = t * x * y - s * z;
    r.m[0][2] = t * x * z + s * y;
    r.m[1][0] = t * x * y + s * z;
    r.m[1][1] = t * y * y + c;
    r.m[1][2] = t * y * z - s * x;
    r.m[2][0] = t * x * z - s * y;
    r.m[2][1] = t * y * z + s * x;
    r.m[2][2] = t * z * z + c;
    return r;
}

namespace {

struct D3 {
    double x, y, z;
};
D3 d3(Vec3 v) {
    return {v.x, v.y, v.z};
}
D3 dcross(D3 a, D3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double dlen(D3 a) {
    return std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
}
D3 dunit(D3 a) {
    double l = dlen(a);
    return {a.x / l, a.y / l, a.z / l};
}

} // namespace

bool Mat4::look_at(Vec3 origin, Vec3 target, Vec3 up, Mat4& out) {
    D3 d{double(target.x) - origin.x, double(target.y) - origin.y, double(target.z) - origin.z};
    if (!(dlen(d) > 0)) return false;
    d = dunit(d);
    D3 left = dcross(d3(up), d);
    if (!(dlen(left) > 1e-9 * dlen(d3(up))) || !(dlen(d3(up)) > 0)) return false;
    left = dunit(left);
    D3 u = dcross(d, left);
    const D3 col[4] = {left, u, d, d3(origin)};
    out = Mat4();
    for (int j = 0; j < 4; ++j) {
        out.m[0][j] = col[j].x;
        out.m[1][j] = col[j].y;
        out.m[2][j] = col[j].z;
    }
    return true;
}

Vec3 Mat4::point(Vec3 p) const {
    double r[3];
    for (int i = 0; i < 3; ++i)
        r[i] = m[i][0] * p.x + m[i][1] * p.y + m[i][2] * p.z + m[i][3];
    return {float(r[0]), float(r[1]), float(r[2])};
}

Vec3 Mat4::vector(Vec3 v) const {
    double r[3];
    for (int i = 0; i < 3; ++i)
        r[i] = m[i][0] * v.x + m[i][1] * v.y + m[i][2] * v.z;
    return {float(r[0]), float(r[1]), float(r[2])};
}

Vec3 Mat4::normal(Vec3 n) const {
    // The inverse transpose is the cofactor matrix over the determinant; the
    // cofactors alone give the direction (times the determinant's sign).
    double c[3][3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            c[i][j] = m[i1][j1] * m[i2][j2] - m[i1][j2] * m[i2][j1];
        }
    const double sign = det3() < 0 ? -1 : 1;
    double r[3];
    for (int i = 0; i < 3; ++i)
        r[i] = sign * (c[i][0] * n.x + c[i][1] * n.y + c[i][2] * n.z);
    return {float(r[0]), float(r[1]), float(r[2])};
}

double Mat4::det3() const {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

bool Mat4::is_identity() const {
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (m[i][j] != (i == j ? 1.0 : 0.0)) return false;
    return true;
}

Mat4 operator*(const Mat4& a, const Mat4& b) {
    Mat4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double s = 0;
            for (int k = 0; k < 4; ++k)
                s += a.m[i][k] * b.m[k][j];
            r.m[i][j] = s;
        }
    return r;
}

} // namespace smallmlt
