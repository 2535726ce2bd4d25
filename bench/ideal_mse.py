"""The MSE of an ideal MLT render: independent samples in proportion to luminance.

    python3 bench/ideal_mse.py [--mask MASK.pfm] REFERENCE.pfm MUTATIONS_PER_PIXEL [IMAGE.pfm ...]

M mutations per pixel spread over the film in proportion to the luminance I
of the reference put a Poisson number of samples with mean M I_j / mean(I)
into pixel j, so each channel c_j of its estimate has variance
c_j^2 mean(I) / (M I_j). Their mean over the film and channels is the MSE a
render would have if its chains were independent and exactly proportional
(no burn-in error, no error in b, no large steps): the floor that chain
correlation raises. Each IMAGE's MSE against the reference (linear RGB, as
`smallmlt compare`) is printed beside it, with its ratio to that floor.

With --mask (the reference's -mask.pfm: the lights seen directly, which the
split renders by per-pixel samples, not chains), the pixels lit in MASK are
left out: the mutations go to the other pixels in proportion to their
luminance, and the MSEs are over those pixels (`mse_unlit`).
Pure Python; a 128x128 film takes a second.
"""
import struct
import sys


def read_pfm(path):
    """(width, height, [r, g, b, r, g, b, ...]) of a colour PFM, rows as stored."""
    try:
        f = open(path, "rb")
    except OSError as e:
        sys.exit(f"{path}: {e.strerror}")
    with f:
        if f.readline().strip() != b"PF":
            sys.exit(f"{path}: not a colour PFM (header 'PF')")
        try:
            width, height = map(int, f.readline().split())
            scale = float(f.readline())
        except ValueError:
            sys.exit(f"{path}: the PFM's size or scale line is not numbers")
        count = width * height * 3
        data = f.read(4 * count)
        if len(data) != 4 * count:
            sys.exit(f"{path}: {len(data)} bytes of pixels, expected {4 * count}")
        order = "<" if scale < 0 else ">"
        return width, height, struct.unpack(f"{order}{count}f", data)


def luminance(rgb, i):
    return 0.2126 * rgb[i] + 0.7152 * rgb[i + 1] + 0.0722 * rgb[i + 2]


def ideal_mse(ref, mutations_per_pixel, kept):
    """Over the pixels in kept, which all M x pixels mutations go to."""
    total_lum = sum(luminance(ref, 3 * j) for j in kept)
    mutations = mutations_per_pixel * (len(ref) // 3)
    total = 0.0
    for j in kept:
        lum = luminance(ref, 3 * j)
        if lum > 0.0:
            channels = sum(ref[3 * j + c] ** 2 for c in range(3)) / 3.0
            total += channels * total_lum / (mutations * lum)
    return total / len(kept)


def mse(image, ref, kept):
    total = sum((image[3 * j + c] - ref[3 * j + c]) ** 2 for j in kept for c in range(3))
    return total / (3 * len(kept))


def main(argv):
    mask_path = None
    if len(argv) > 2 and argv[1] == "--mask":
        mask_path = argv[2]
        argv = argv[:1] + argv[3:]
    if len(argv) < 3:
        sys.exit(__doc__.strip().split("\n\n")[1])
    w, h, ref = read_pfm(argv[1])
    kept = range(w * h)
    if mask_path:
        mw, mh, mask = read_pfm(mask_path)
        if (mw, mh) != (w, h):
            sys.exit(f"{mask_path}: {mw}x{mh}, the reference is {w}x{h}")
        kept = [j for j in kept if luminance(mask, 3 * j) == 0.0]
    if not any(luminance(ref, 3 * j) > 0.0 for j in kept):
        where = f" outside the lit pixels of {mask_path}" if mask_path else ""
        sys.exit(f"{argv[1]}: no pixel{where} has a positive luminance")
    try:
        mutations = float(argv[2])
    except ValueError:
        sys.exit(f"MUTATIONS_PER_PIXEL: '{argv[2]}' is not a number")
    if not mutations > 0.0:
        sys.exit(f"MUTATIONS_PER_PIXEL: must be positive, got {argv[2]}")
    floor = ideal_mse(ref, mutations, kept)
    name = "mse_unlit" if mask_path else "mse"
    print(f"ideal independent MLT at {mutations:g} mutations per pixel: {name} {floor:.4g}")
    for path in argv[3:]:
        iw, ih, image = read_pfm(path)
        if (iw, ih) != (w, h):
            sys.exit(f"{path}: {iw}x{ih}, the reference is {w}x{h}")
        err = mse(image, ref, kept)
        print(f"{path}: {name} {err:.4g}, {err / floor:.2f} times the ideal")


if __name__ == "__main__":
    main(sys.argv)
