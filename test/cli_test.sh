#!/bin/sh
# Command-line behaviour of the smallmlt binary: exit codes, messages that
# name the flag or file, and no output file when a render fails.
# Usage: cli_test.sh BIN. Prints one line per check and "N passed, N failed".
set -u
BIN=$1
DIR=build/test-scratch/cli
rm -rf "$DIR" && mkdir -p "$DIR"
. test/checks.sh

check help 0 "smallmlt render SCENE" -- "$BIN" --help
check render_help 0 "--spp N" -- "$BIN" render --help
check budget_help 0 "--format table|csv|json" -- "$BIN" budget --help
check compare_help 0 "smallmlt compare IMAGE REFERENCE" -- "$BIN" compare --help
check devices_help 0 "smallmlt devices" -- "$BIN" devices -h
check version 0 "smallmlt " -- "$BIN" --version
check devices 0 "global memory" -- "$BIN" devices
mkdir -p "$DIR/no-vendors"
check no_platform 1 "no OpenCL platform found" -- env OCL_ICD_VENDORS="$DIR/no-vendors" "$BIN" devices
check no_platform_render 1 "no OpenCL platform found" -- env OCL_ICD_VENDORS="$DIR/no-vendors" "$BIN" render scenes/cornell.scene --out "$DIR/np.png"
absent no_platform_no_file "$DIR/np.png"
check no_command 2 "no command given" -- "$BIN"
check unknown_command 2 "unknown command 'draw'" -- "$BIN" draw
check unknown_flag 2 "unknown option --fast" -- "$BIN" render scenes/cornell.scene --fast
check spp_zero 2 "--spp: 0 is out of range" -- "$BIN" render scenes/cornell.scene --spp 0
check spp_text 2 "--spp: 'many' is not an integer" -- "$BIN" render scenes/cornell.scene --spp many
check spp_missing 2 "--spp: missing value" -- "$BIN" render scenes/cornell.scene --spp
check time_negative 2 "--time: '-1' is not a positive" -- "$BIN" render scenes/cornell.scene --time -1
check time_nan 2 "--time: 'nan' is not a positive" -- "$BIN" render scenes/cornell.scene --time nan
check spp_and_time 2 "give one of them" -- "$BIN" render scenes/cornell.scene --spp 1 --time 1
check depth_range 2 "--depth: 99 is out of range 0..64" -- "$BIN" render scenes/cornell.scene --depth 99
check width_zero 2 "--width: 0 is out of range" -- "$BIN" render scenes/cornell.scene --width 0
check out_format 2 "--out $DIR/x.jpg: unknown image format" -- "$BIN" render scenes/cornell.scene --out "$DIR/x.jpg"
check out_dir 2 "does not exist or is not writable" -- "$BIN" render scenes/cornell.scene --out "$DIR/no/x.png"
check device_range 2 "--device: index 99 out of range" -- "$BIN" render scenes/cornell.scene --device 99 --out "$DIR/dev.png"
absent device_range_no_file "$DIR/dev.png"
check no_scene 2 "no scene file given" -- "$BIN" render
check missing_scene 1 "nope.scene: cannot open scene file" -- "$BIN" render nope.scene --out "$DIR/missing.png"
absent missing_scene_no_file "$DIR/missing.png"
printf 'film 8 8\nlens 1\n' > "$DIR/bad.scene"
check bad_scene 1 "bad.scene:2: unknown directive 'lens'" -- "$BIN" render "$DIR/bad.scene" --out "$DIR/bad.png"
absent bad_scene_no_file "$DIR/bad.png"
check render_ok 0 "8x8, depth 8, pt: " -- "$BIN" render scenes/cornell.scene --method pt --width 8 --height 8 --spp 2 --out "$DIR/ok.png" --out "$DIR/ok.pfm"
check render_mlt 0 "mlt: " -- "$BIN" render scenes/cornell.scene --width 8 --height 8 --spp 2 --method mlt --threads 64 --out "$DIR/mlt.pfm"
check mlt_default 0 "mlt: " -- "$BIN" render scenes/cornell.scene --width 8 --height 8 --spp 1 --threads 64 --out "$DIR/default.png"
check burn_in_bad 2 "--burn-in: 'mcmc' is not a burn-in" -- "$BIN" render scenes/cornell.scene --burn-in mcmc
check burn_in_iters_zero 2 "--burn-in-iters: 0 is out of range" -- "$BIN" render scenes/cornell.scene --burn-in-iters 0
# One method's flags with the other: a warning each, and the render.
check pt_mlt_flags 0 "smallmlt: warning: --path-step changes nothing with --method pt (ignored)" -- "$BIN" render scenes/cornell.scene --method pt --path-step 64 --film-step 8 --width 8 --height 8 --spp 1 --quiet --out "$DIR/ptflags.pfm"
check pt_mlt_flags_each 0 "smallmlt: warning: --film-step changes nothing with --method pt (ignored)" -- "$BIN" render scenes/cornell.scene --film-step 8 --method pt --width 8 --height 8 --spp 1 --quiet --out "$DIR/ptflags.pfm"
check mlt_pt_flags 0 "smallmlt: warning: --sampler changes nothing with --method mlt (ignored)" -- "$BIN" render scenes/cornell.scene --sampler random --width 8 --height 8 --spp 1 --threads 64 --quiet --out "$DIR/mltflags.pfm"
check path_step_range 2 "--path-step: 8 is out of range 16..1024" -- "$BIN" render scenes/cornell.scene --path-step 8
check path_step_power 2 "--path-step: 100 is not a power of two" -- "$BIN" render scenes/cornell.scene --path-step 100
# A lamp above a grey triangle, emitting upwards into nothing: the scene is
# lit in principle and black in fact; and the same without the lamp.
printf 'newmtl grey\nKd 0.5 0.5 0.5\nnewmtl lamp\nKe 5 5 5\n' > "$DIR/dark.mtl"
printf 'mtllib dark.mtl\nv -1 0 -1\nv 1 0 -1\nv 0 2 -1\nv -1 5 -1\nv 1 5 -1\nv 0 5 1\nusemtl grey\nf 1 2 3\nusemtl lamp\nf 4 6 5\n' > "$DIR/dark.obj"
printf 'camera 0 1 3  0 1 0  0 1 0  40\nmesh dark.obj\n' > "$DIR/dark.scene"
check black_scene 0 "carried light (b = 0): the image is black" -- "$BIN" render "$DIR/dark.scene" --width 8 --height 8 --threads 64 --out "$DIR/dark.pfm"
check black_scene_is_black 0 "mse 0 rel_mse 0 mean 0 reference_mean 0" -- "$BIN" compare "$DIR/dark.pfm" "$DIR/dark.pfm"
# MTL lines that change nothing: the render (even --quiet) and the budget
# warn on stderr, once for the file.
printf 'newmtl grey\nKd 0.5 0.5 0.5\nKa 1 1 1\nnewmtl lamp\nKe 5 5 5\nKa 1 1 1\n' > "$DIR/warn.mtl"
sed 's/dark.mtl/warn.mtl/' "$DIR/dark.obj" > "$DIR/warn.obj"
sed 's/dark.obj/warn.obj/' "$DIR/dark.scene" > "$DIR/warn.scene"
warning="smallmlt: $DIR/warn.mtl:3: warning: 'Ka' changes nothing in these models (ignored; 2 lines)"
check mtl_warning 0 "$warning" -- "$BIN" render "$DIR/warn.scene" --method pt --width 8 --height 8 --spp 1 --quiet --out "$DIR/warn.pfm"
check budget_mtl_warning 0 "$warning" -- "$BIN" budget "$DIR/warn.scene" --depth 1
# A texture map whose file is missing: an error naming the MTL line and
# the file, from the render and the budget, and no image.
printf 'newmtl grey\nKd 0.5 0.5 0.5\nmap_Kd -bm 1 nope.png\nnewmtl lamp\nKe 5 5 5\n' > "$DIR/notex.mtl"
sed 's/dark.mtl/notex.mtl/' "$DIR/dark.obj" > "$DIR/notex.obj"
sed 's/dark.obj/notex.obj/' "$DIR/dark.scene" > "$DIR/notex.scene"
check texture_missing 1 "$DIR/notex.mtl:3: cannot read texture $DIR/nope.png: " -- "$BIN" render "$DIR/notex.scene" --method pt --width 8 --height 8 --spp 1 --out "$DIR/notex.png"
absent texture_missing_no_file "$DIR/notex.png"
check budget_texture_missing 1 "$DIR/notex.mtl:3: cannot read texture $DIR/nope.png: " -- "$BIN" budget "$DIR/notex.scene" --depth 1
grep -v lamp "$DIR/dark.obj" > "$DIR/unlit.obj"
sed 's/dark.obj/unlit.obj/' "$DIR/dark.scene" > "$DIR/unlit.scene"
check no_light 1 "unlit.scene: no emissive triangle" -- "$BIN" render "$DIR/unlit.scene" --out "$DIR/unlit.png"
absent no_light_no_file "$DIR/unlit.png"
# On a device of 4 GiB: what PoCL reports is a share of the memory free at
# the time (up to 22 GiB here, which this film fits, and the host then ran
# out of memory).
check film_enormous 1 "not enough device memory" -- "$BIN" render scenes/cornell.scene --width 16384 --height 16384 --device-mem 4G --out "$DIR/huge.png"
absent film_enormous_no_file "$DIR/huge.png"
check device_mem_tiny 1 "not enough device memory" -- "$BIN" render scenes/cornell-water.scene --device-mem 64K --out "$DIR/tiny.png"
absent device_mem_tiny_no_file "$DIR/tiny.png"
check threads_too_many 2 "threads fit (or use --threads auto)" -- "$BIN" render scenes/cornell-water.scene --threads 4000000 --device-mem 64M --out "$DIR/many.png"
absent threads_too_many_no_file "$DIR/many.png"
check device_mem_bad 2 "--device-mem: '12Q' is not a size in bytes" -- "$BIN" render scenes/cornell.scene --device-mem 12Q
check budget_table 0 "B/chain pack" -- "$BIN" budget scenes/cornell-water.scene --depth 4
check budget_csv 0 "depth,bits_per_bounce,chain_bytes_packed" -- "$BIN" budget scenes/cornell.scene --format csv --threads 1024
check budget_json 0 "\"reduction\":" -- "$BIN" budget scenes/cornell.scene --format json --threads 1024 --proposals 4
check budget_proposals 2 "--proposals: 3 is not a power of two" -- "$BIN" budget scenes/cornell.scene --proposals 3
check budget_small 0 "(emulated)" -- "$BIN" budget scenes/cornell-water.scene --device-mem 64M
check budget_too_small 1 "it would take 12.9 MiB of device memory (--weights expected halves its film of 6.0 MiB)" -- "$BIN" budget scenes/cornell-water.scene --device-mem 4M
check budget_too_small_expected 1 "it would take 6.9 MiB of device memory" -- "$BIN" budget scenes/cornell-water.scene --device-mem 4M --weights expected
check budget_film 0 "film 512x512: 6.0 MiB in 2 band(s)" -- "$BIN" budget scenes/cornell-water.scene --device-mem 16M
check budget_uhd 0 "film 3840x2160: 94.9 MiB in 2 band(s)" -- "$BIN" budget scenes/cornell.scene --width 3840 --height 2160 --device-mem 256M --depth 1 --weights expected
# Kelemen's weights (the default) keep the large steps' estimate in a second
# layer of the film: twice the memory, which 256 MiB cannot hold at 4K.
check budget_uhd_kelemen 0 "film 3840x2160: 189.8 MiB in" -- "$BIN" budget scenes/cornell.scene --width 3840 --height 2160 --device-mem 1G --depth 1
check budget_uhd_kelemen_too_big 1 "(--weights expected halves its film of 189.8 MiB)" -- "$BIN" budget scenes/cornell.scene --width 3840 --height 2160 --device-mem 256M --depth 1
check budget_profile 0 "adreno-650 (emulated on" -- "$BIN" budget scenes/cornell-water.scene --profile adreno-650 --depth 1
check profile_bad 2 "--profile: 'mali' is not a device profile (mali-g610, adreno-650" -- "$BIN" render scenes/cornell.scene --profile mali
check profile_vc4 1 "runs work-groups of at most 12 work-items" -- "$BIN" render scenes/cornell.scene --profile videocore-iv --out "$DIR/vc4.png"
absent profile_vc4_no_file "$DIR/vc4.png"
check film_atomics_bad 2 "--film-atomics: '16' is not 32 or 64" -- "$BIN" render scenes/cornell.scene --film-atomics 16
check film64_needs_int64 1 "leave out --film-atomics 64" -- "$BIN" render scenes/cornell.scene --profile adreno-650 --film-atomics 64 --width 8 --height 8 --out "$DIR/f64.png"
absent film64_needs_int64_no_file "$DIR/f64.png"
# The film's targets on small devices: cornell-water at its own 512x512 film
# and depth 24 on 16 MiB (largest allocation 4 MiB), by MLT and by PT.
check water_16m_mlt 0 "threads: 2048 (auto: 16384 keep the device busy, reduced 8x to fit); film 6.0 MiB in 2 band(s); device memory 7.4 MiB of 8.0 MiB allowed" -- "$BIN" render scenes/cornell-water.scene --device-mem 16M --spp 1 --out "$DIR/w16.pfm"
check water_16m_mlt_expected 0 "threads: 8192 (auto: 16384 keep the device busy, reduced 2x to fit); film 3.0 MiB in 1 band(s); device memory 7.4 MiB of 8.0 MiB allowed" -- "$BIN" render scenes/cornell-water.scene --device-mem 16M --spp 1 --weights expected --out "$DIR/w16e.pfm"
check water_16m_pt 0 "film: 3.0 MiB in 1 band(s)" -- "$BIN" render scenes/cornell-water.scene --method pt --device-mem 16M --spp 1 --out "$DIR/w16p.pfm"
check proposals_ok 0 "x 4 proposals" -- "$BIN" render scenes/cornell.scene --width 8 --height 8 --spp 4 --threads 256 --proposals 4 --out "$DIR/k4.pfm"
check proposals_pow2 2 "--proposals: 3 is not a power of two" -- "$BIN" render scenes/cornell.scene --proposals 3
check proposals_multiple 2 "--threads 100 is not a multiple of --proposals 8" -- "$BIN" render scenes/cornell.scene --threads 100 --proposals 8 --out "$DIR/k8.png"
absent proposals_multiple_no_file "$DIR/k8.png"
if "$BIN" devices | head -n 1 | grep -q "Portable Computing Language"; then
    # PoCL shrinks the memory it reports; the budget must follow it.
    check pocl_memory_limit 0 "device memory 1.0 GiB" -- env POCL_MEMORY_LIMIT=1 "$BIN" budget scenes/cornell.scene --depth 1
    # A 3840x2160 film on a device of 1 GiB, emulating 256 MiB (largest
    # allocation 64 MiB): the film goes in two bands, by PT and by MLT (for
    # half a second: what is tested is that it fits and renders, and
    # test_film.cpp tests what bands render).
    check uhd_pt 0 "film: 94.9 MiB in 2 band(s)" -- env POCL_MEMORY_LIMIT=1 "$BIN" render scenes/cornell.scene --width 3840 --height 2160 --depth 0 --device-mem 256M --method pt --spp 1 --out "$DIR/uhd.pfm"
    check uhd_mlt 0 "film 94.9 MiB in 2 band(s)" -- env POCL_MEMORY_LIMIT=1 "$BIN" render scenes/cornell.scene --width 3840 --height 2160 --depth 1 --device-mem 256M --threads 1024 --burn-in-iters 1 --weights expected --time 0.5 --out "$DIR/uhdm.pfm"
    # PFM: a header, then 3840 x 2160 x 3 floats.
    uhd_written() { [ "$(wc -c < "$DIR/uhdm.pfm")" -gt 99532800 ] && [ "$(wc -c < "$DIR/uhd.pfm")" -gt 99532800 ]; }
    truth uhd_images uhd_written
    rm -f "$DIR/uhd.pfm" "$DIR/uhdm.pfm"
    # A platform without devices.
    check no_device 1 "no OpenCL device found on any platform" -- env POCL_DEVICES=none "$BIN" render scenes/cornell.scene --out "$DIR/nd.png"
    absent no_device_no_file "$DIR/nd.png"
fi
check method_bad 2 "--method: 'bdpt' is not a method" -- "$BIN" render scenes/cornell.scene --method bdpt
check split_name 2 "--split indirect: expected none, visible, direct, all or auto" -- "$BIN" render scenes/cornell.scene --split indirect
check omc_effort_negative 2 "--omc-effort: '-1' is not a number >= 0" -- "$BIN" render scenes/cornell.scene --omc-effort -1
check split_summary 0 "split visible: OMC part" -- "$BIN" render scenes/cornell.scene --split visible --threads 1024 --burn-in-iters 2 --width 16 --height 16 --spp 8 --out "$DIR/split.png"
check target_name 2 "--target: 'kelemen' is not a target (luminance or two-stage)" -- "$BIN" render scenes/cornell.scene --target kelemen
check omc_cells_name 2 "--omc-cells auto: expected on or off" -- "$BIN" render scenes/cornell.scene --omc-cells auto
check weights_name 2 "--weights: 'veach' is not a weighting (expected or kelemen)" -- "$BIN" render scenes/cornell.scene --weights veach
check target_summary 0 "target two-stage (" -- "$BIN" render scenes/cornell-water.scene --split visible --target two-stage --threads 1024 --burn-in-iters 4 --width 16 --height 16 --spp 8 --out "$DIR/two-stage.png"
check weights_summary 0 "Kelemen's weights (M p b0 = " -- "$BIN" render scenes/cornell-water.scene --split visible --weights kelemen --restart 0 --threads 1024 --burn-in-iters 4 --width 16 --height 16 --spp 8 --out "$DIR/kelemen.png"
# --restart auto: 1,024 chains on 256 pixels restart every 8 steps (20 steps: twice).
check restart_summary 0 "; chains restarted every 8 steps, 2 times, their samples large steps'" -- "$BIN" render scenes/cornell-water.scene --split visible --restart auto --threads 1024 --burn-in-iters 4 --width 16 --height 16 --spp 80 --out "$DIR/restart.png"
check restart_weights 0 "Kelemen's weights (M c b0 = " -- "$BIN" render scenes/cornell-water.scene --split visible --restart auto --threads 1024 --burn-in-iters 4 --width 16 --height 16 --spp 80 --out "$DIR/restart.png"
check large_step_range 2 "--large-step: '1.5' is not a probability" -- "$BIN" render scenes/cornell.scene --large-step 1.5
check sampler_bad 2 "--sampler: 'halton' is not a sampler (sobol or random)" -- "$BIN" render scenes/cornell.scene --sampler halton
check rr_threshold_zero 2 "--rr-threshold: '0' is not a positive number" -- "$BIN" render scenes/cornell.scene --rr-threshold 0
check rr_cap_zero 2 "--rr-cap: 0 would end every path" -- "$BIN" render scenes/cornell.scene --rr-cap 0
check rr_cap_range 2 "--rr-cap: '1.5' is not a probability" -- "$BIN" render scenes/cornell.scene --rr-cap 1.5
check rr_by_bad 2 "--rr-by: 'min' is not a measure (max or luminance)" -- "$BIN" render scenes/cornell.scene --rr-by min
check rr_start_range 2 "--rr-start: 65 is out of range" -- "$BIN" render scenes/cornell.scene --rr-start 65
check threads_zero 2 "--threads: 0 is out of range" -- "$BIN" render scenes/cornell.scene --threads 0
check stuck_run_zero 2 "--stuck-run: 0 is out of range" -- "$BIN" render scenes/cornell.scene --stuck-run 0
# The stuck note, with a run of 2 counting as stuck: among 256 chains of 64
# steps some reject twice in a row whatever the seed (about 2 in 3 do).
check stuck_note 0 "stayed on one path for 2 steps or more" -- "$BIN" render scenes/cornell.scene --width 8 --height 8 --threads 256 --spp 64 --split none --stuck-run 2 --out "$DIR/stuck.pfm"
check stuck_summary 0 "longest run of rejections" -- "$BIN" render scenes/cornell.scene --width 8 --height 8 --spp 4 --threads 64 --out "$DIR/stuck2.pfm"
check render_quiet 0 "" -- "$BIN" render scenes/cornell.scene --width 8 --height 8 --spp 1 --quiet --out "$DIR/q.exr"
for f in ok.png ok.pfm q.exr mlt.pfm default.png dark.pfm w16.pfm w16p.pfm; do
    if [ -s "$DIR/$f" ]; then pass=$((pass + 1)); echo "ok   wrote $f"; else fail=$((fail + 1)); echo "FAIL $f missing"; fi
done
"$BIN" render scenes/cornell.scene --method pt --width 4 --height 4 --spp 1 --quiet --out "$DIR/small.pfm"
check compare_ok 0 "mse 0 rel_mse 0" -- "$BIN" compare "$DIR/ok.pfm" "$DIR/ok.pfm"
check compare_size 1 "image is 8x8, reference 4x4" -- "$BIN" compare "$DIR/ok.pfm" "$DIR/small.pfm"
check compare_missing 1 "nope.pfm: cannot open image" -- "$BIN" compare "$DIR/ok.pfm" "$DIR/nope.pfm"
check compare_args 2 "compare: give IMAGE and REFERENCE" -- "$BIN" compare "$DIR/ok.pfm"
check compare_png 2 "only .pfm and .exr" -- "$BIN" compare "$DIR/ok.png" "$DIR/ok.pfm"
check compare_mask 0 "block8_mse 0 block32_mse 0 mse_unlit 0" -- "$BIN" compare --mask "$DIR/ok.pfm" "$DIR/ok.pfm" "$DIR/ok.pfm"
check compare_mask_size 1 "$DIR/small.pfm: mask is 4x4, image 8x8" -- "$BIN" compare "$DIR/ok.pfm" "$DIR/ok.pfm" --mask "$DIR/small.pfm"
check compare_mask_missing 2 "--mask: missing value" -- "$BIN" compare "$DIR/ok.pfm" "$DIR/ok.pfm" --mask
check compare_unknown_option 2 "unknown option --masks" -- "$BIN" compare "$DIR/ok.pfm" "$DIR/ok.pfm" --masks x.pfm
check compare_too_many 2 "compare: unexpected argument 'x.pfm'" -- "$BIN" compare "$DIR/ok.pfm" "$DIR/ok.pfm" x.pfm
no_temporaries "$DIR"
summary cli
