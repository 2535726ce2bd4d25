/* Primary-sample-space chain states in device memory, after Kelemen et al.
 * 2002 with the storage of Frolov and Galaktionov (section 3.2): each number
 * is kept at its slot's precision (24 or 16 bits, layout.cl), packed into a
 * contiguous bit stream of 32-bit words with no padding. Word w of chain c is
 * at state[w * stride + c] (stride = number of chains), so neighbouring
 * work-items touch neighbouring words.
 *
 * With PSS_FLOAT32 defined, every number is stored unpacked as a 32-bit float
 * in its own word and mutated in float arithmetic: the reference build that
 * tests compare the packed one against. */

#ifndef PSS_FLOAT32

/* Integer value of `bits` bits at bit offset `off` of chain `chain`. */
inline uint pss_read_bits(const __global uint* state, uint chain, uint stride, uint off,
                          uint bits) {
    uint w = off >> 5, shift = off & 31u;
    uint v = state[w * stride + chain] >> shift;
    if (shift + bits > 32u) v |= state[(w + 1u) * stride + chain] << (32u - shift);
    return v & ((1u << bits) - 1u);
}

inline void pss_write_bits(__global uint* state, uint chain, uint stride, uint off, uint bits,
                           uint v) {
    uint w = off >> 5, shift = off & 31u;
    uint mask = (1u << bits) - 1u;
    __global uint* lo = &state[w * stride + chain];
    *lo = (*lo & ~(mask << shift)) | (v << shift);
    if (shift + bits > 32u) {
        __global uint* hi = &state[(w + 1u) * stride + chain];
        uint hi_bits = shift + bits - 32u;
        *hi = (*hi & ~((1u << hi_bits) - 1u)) | (v >> (32u - shift));
    }
}

/* A chain's number in slot `at` as a float in [0, 1) (a multiple of 2^-bits). */
inline float pss_load(const __global uint* state, uint chain, uint stride, LayoutSlot at) {
    return layout_unit(pss_read_bits(state, chain, stride, at.bit_offset, at.bits), at.bits);
}

/* Stores u, which must lie on the slot's grid (as pss_load and the
 * proposals of sample_chain.cl produce). */
inline void pss_store(__global uint* state, uint chain, uint stride, LayoutSlot at, float u) {
    pss_write_bits(state, chain, stride, at.bit_offset, at.bits,
                   (uint)(u * (float)(1u << at.bits)));
}

/* Sequential writer of a chain's numbers in bit-stream order, one store per
 * word. A commit writes the live numbers from the start; what follows them
 * belongs to dead numbers that are never read, so the last word is written
 * whole. A number's old value may still be read after earlier numbers have
 * been put: a word is stored only once every number overlapping it is. */
typedef struct {
    ulong bits; /* pending bits, lowest first */
    uint count; /* number of pending bits */
    uint word;  /* index of the next word to store */
} PssWriter;

inline PssWriter pss_writer(void) {
    PssWriter w = {0ul, 0u, 0u};
    return w;
}

/* Puts the next number, the integer v < 2^bits. */
inline void pss_put(PssWriter* w, __global uint* state, uint chain, uint stride, uint bits,
                    uint v) {
    w->bits |= (ulong)v << w->count;
    w->count += bits;
    if (w->count >= 32u) {
        state[w->word * stride + chain] = (uint)w->bits;
        w->bits >>= 32;
        w->count -= 32u;
        ++w->word;
    }
}

inline void pss_finish(PssWriter* w, __global uint* state, uint chain, uint stride) {
    if (w->count > 0u) state[w->word * stride + chain] = (uint)w->bits;
}

#else

inline float pss_load(const __global uint* state, uint chain, uint stride, LayoutSlot at) {
    return as_float(state[at.dim * stride + chain]);
}

inline void pss_store(__global uint* state, uint chain, uint stride, LayoutSlot at, float u) {
    state[at.dim * stride + chain] = as_uint(u);
}

/* One word per number: a commit stores each number as it comes. */
typedef struct {
    uint unused;
} PssWriter;

inline PssWriter pss_writer(void) {
    PssWriter w = {0u};
    return w;
}

inline void pss_finish(PssWriter* w, __global uint* state, uint chain, uint stride) {}

#endif
