/* Fresnel reflectance, unpolarized: of a smooth interface between
 * dielectrics, and of a conductor of complex index eta + i k (the closed
 * form of the s and p amplitudes, e.g. Born and Wolf). */

/* cos_i >= 0 on the incident side, eta = eta_incident / eta_transmitted.
 * Sets *cos_t (>= 0) for refraction; total internal reflection gives 1. */
inline float fresnel_dielectric(float cos_i, float eta, float* cos_t) {
    float sin2_t = eta * eta * fmax(0.0f, 1.0f - cos_i * cos_i);
    if (sin2_t >= 1.0f) {
        *cos_t = 0.0f;
        return 1.0f;
    }
    float ct = sqrt(1.0f - sin2_t);
    *cos_t = ct;
    float r_s = (eta * cos_i - ct) / (eta * cos_i + ct);
    float r_p = (cos_i - eta * ct) / (cos_i + eta * ct);
    return 0.5f * (r_s * r_s + r_p * r_p);
}

/* The same for a refraction whose both cosines are known (cos_i on the
 * incident side, cos_t on the other, eta_t = eta_transmitted /
 * eta_incident): symmetric under exchanging the sides. */
inline float fresnel_refracted(float cos_i, float cos_t, float eta_t) {
    float r_s = (cos_i - eta_t * cos_t) / (cos_i + eta_t * cos_t);
    float r_p = (eta_t * cos_i - cos_t) / (eta_t * cos_i + cos_t);
    return 0.5f * (r_s * r_s + r_p * r_p);
}

/* Per channel, for cos_i in [0, 1] and the conductor's index relative to
 * the incident medium. eta 0, k 1 gives 1 at every angle. */
inline float3 fresnel_conductor(float cos_i, float3 eta, float3 k) {
    float c2 = cos_i * cos_i, s2 = 1.0f - c2;
    float3 t0 = eta * eta - k * k - s2;
    float3 a2b2 = sqrt(t0 * t0 + 4.0f * eta * eta * k * k);
    float3 a = sqrt(fmax(0.5f * (a2b2 + t0), 0.0f));
    float3 t1 = a2b2 + c2, t2 = 2.0f * cos_i * a;
    float3 r_s = (t1 - t2) / (t1 + t2);
    float3 t3 = c2 * a2b2 + s2 * s2, t4 = t2 * s2;
    float3 r_p = r_s * (t3 - t4) / (t3 + t4);
    return 0.5f * (r_s + r_p);
}
