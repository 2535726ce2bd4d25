/* Microfacet distributions of the rough models, GGX (Trowbridge-Reitz) and
 * Beckmann, isotropic with roughness alpha, in the local frame (z up), with
 * Smith's masking (separable: G = G1(wo) G1(wi)) and sampling of the normals
 * visible from wo: Heitz 2018 for GGX; for Beckmann, the stretched slope
 * space of Heitz and d'Eon 2014, its slope CDF inverted by Newton steps. */

/* D(m) for m.z > 0; the integral of D(m) m.z over the hemisphere is 1. */
inline float mf_d(float3 m, float alpha, bool beckmann) {
    if (m.z <= 0.0f) return 0.0f;
    float a2 = alpha * alpha, z2 = m.z * m.z, xy2 = m.x * m.x + m.y * m.y;
    if (beckmann) return exp(-xy2 / (z2 * a2)) / (M_PI_F * a2 * z2 * z2);
    float d = xy2 / a2 + z2;
    return 1.0f / (M_PI_F * a2 * d * d);
}

/* Smith's Lambda(w) of the distribution. */
inline float mf_lambda(float3 w, float alpha, bool beckmann) {
    float xy = sqrt(w.x * w.x + w.y * w.y), z = fabs(w.z);
    if (xy == 0.0f) return 0.0f;
    if (beckmann) {
        float a = z / (alpha * xy); /* 1 / (alpha tan theta) */
        return 0.5f * (exp(-a * a) / (a * 1.7724539f) - erfc(a));
    }
    float t = alpha * xy / z; /* alpha tan theta */
    return 0.5f * (sqrt(1.0f + t * t) - 1.0f);
}

/* Masking of w by microfacets of normal m: 0 where w sees m's back. */
inline float mf_g1(float3 w, float3 m, float alpha, bool beckmann) {
    if (dot(w, m) * w.z <= 0.0f) return 0.0f;
    return 1.0f / (1.0f + mf_lambda(w, alpha, beckmann));
}

/* The density of mf_sample_visible: G1(wo) max(0, wo.m) D(m) / wo.z. */
inline float mf_pdf_visible(float3 wo, float3 m, float alpha, bool beckmann) {
    if (wo.z <= 0.0f) return 0.0f;
    return mf_g1(wo, m, alpha, beckmann) * fmax(dot(wo, m), 0.0f) * mf_d(m, alpha, beckmann) / wo.z;
}

/* erf^-1(y) for |y| < 1: Winitzki's closed form, then two Newton steps. */
inline float mf_erfinv(float y) {
    float l = log(fmax((1.0f - y) * (1.0f + y), 1e-30f));
    float c = 4.3307468f + 0.5f * l; /* 2 / (pi a) + l / 2, a = 0.147 */
    float x = copysign(sqrt(sqrt(c * c - l * 6.8027211f) - c), y);
    for (int i = 0; i < 2; ++i)
        x -= (erf(x) - y) * 0.88622693f * exp(x * x);
    return x;
}

/* Slopes of the Beckmann distribution of alpha 1 visible from a direction at
 * angle theta (cos_t, sin_t) in the xz-plane: y is normal with variance 1/2;
 * x < cot theta has density proportional to (1 - x tan theta) exp(-x^2),
 * whose CDF C(x) = sqrt(pi)/2 (1 + erf x) + tan theta / 2 exp(-x^2) is
 * inverted by Newton steps kept inside a bisection bracket. */
inline float2 mf_beckmann_slopes(float cos_t, float sin_t, float u1, float u2) {
    float y = mf_erfinv(fmin(fmax(2.0f * u2 - 1.0f, -0.99999994f), 0.99999994f));
    if (sin_t < 1e-4f)
        return (float2)(mf_erfinv(fmin(fmax(2.0f * u1 - 1.0f, -0.99999994f), 0.99999994f)), y);
    float tan_t = sin_t / cos_t, cot_t = cos_t / sin_t;
    float total = 0.88622693f * (1.0f + erf(cot_t)) + 0.5f * tan_t * exp(-cot_t * cot_t);
    float target = u1 * total;
    float lo = -6.0f, hi = cot_t, x = fmin(0.0f, cot_t - 0.5f);
    for (int i = 0; i < 24; ++i) {
        float e = exp(-x * x);
        float c = 0.88622693f * (1.0f + erf(x)) + 0.5f * tan_t * e - target;
        if (fabs(c) <= 1e-6f * total) break;
        if (c > 0.0f)
            hi = x;
        else
            lo = x;
        float dc = (1.0f - x * tan_t) * e;
        float next = dc > 0.0f ? x - c / dc : lo - 1.0f;
        x = (next > lo && next < hi) ? next : 0.5f * (lo + hi);
    }
    return (float2)(x, y);
}

/* A microfacet normal visible from wo (wo.z > 0), density mf_pdf_visible. */
inline float3 mf_sample_visible(float3 wo, float alpha, bool beckmann, float u1, float u2) {
    /* The configuration stretched to alpha 1. */
    float3 v = normalize((float3)(alpha * wo.x, alpha * wo.y, wo.z));
    float3 m;
    if (beckmann) {
        float xy = sqrt(v.x * v.x + v.y * v.y);
        float cos_p = xy > 0.0f ? v.x / xy : 1.0f, sin_p = xy > 0.0f ? v.y / xy : 0.0f;
        float2 s = mf_beckmann_slopes(v.z, xy, u1, u2);
        float sx = cos_p * s.x - sin_p * s.y, sy = sin_p * s.x + cos_p * s.y;
        m = (float3)(-alpha * sx, -alpha * sy, 1.0f);
    } else {
        /* Heitz 2018: a point on the projected disk, the half facing away
         * from v squeezed by v's tilt, lifted onto the hemisphere. */
        float len2 = v.x * v.x + v.y * v.y;
        float3 t1 =
            len2 > 0.0f ? (float3)(-v.y, v.x, 0.0f) * rsqrt(len2) : (float3)(1.0f, 0.0f, 0.0f);
        float3 t2 = cross(v, t1);
        float r = sqrt(u1);
        float cos_phi;
        float sin_phi = sincos(2.0f * M_PI_F * u2, &cos_phi);
        float p1 = r * cos_phi, p2 = r * sin_phi;
        float s = 0.5f * (1.0f + v.z);
        p2 = (1.0f - s) * sqrt(fmax(0.0f, 1.0f - p1 * p1)) + s * p2;
        float3 h = p1 * t1 + p2 * t2 + sqrt(fmax(0.0f, 1.0f - p1 * p1 - p2 * p2)) * v;
        m = (float3)(alpha * h.x, alpha * h.y, fmax(h.z, 0.0f));
    }
    return normalize(m);
}
