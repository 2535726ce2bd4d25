/* A bounce's numbers by slot, from whichever sample source the program was
 * built with (smp_uniform of sample_sobol.cl, sample_omc.cl or
 * sample_chain.cl). Slots are those of layout.cl (SLOT_*). */

#if LAYOUT_BOUNCE_DIMS > 0
/* Number `slot` of bounce `bounce`, in [0, 1). */
inline float smp_number(SampleSource* src, uint bounce, int slot) {
    return smp_uniform(src, bounce, layout_slot(bounce, slot));
}
#endif
