"""Where an image's error lies: its squared error binned by the reference's luminance.

    python3 bench/error_by_luminance.py [--bins N] REFERENCE.pfm IMAGE.pfm ...

The reference's pixels are sorted by luminance and cut into N bins of equal
pixel count (default 10). For each bin: its luminance range, its share of the
reference's luminance (the share of an MLT render's mutations that land
there, its chains' target being luminance), and for each IMAGE the MSE over
the bin's pixels (linear RGB, as `smallmlt compare`) with the bin's share of
the image's summed squared error. Pure Python, on bench/ideal_mse.py's PFM
reader and MSE.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from ideal_mse import luminance, mse, read_pfm  # noqa: E402


def main(argv):
    bins = 10
    if argv[:1] == ["--bins"]:
        try:
            bins = int(argv[1])
        except (IndexError, ValueError):
            sys.exit("--bins: expected a whole number")
        argv = argv[2:]
    if len(argv) < 2 or bins < 1:
        sys.exit(__doc__.strip().splitlines()[2].strip())
    width, height, ref = read_pfm(argv[0])
    images = []
    for path in argv[1:]:
        w, h, image = read_pfm(path)
        if (w, h) != (width, height):
            sys.exit(f"{path}: {w}x{h}, the reference is {width}x{height}")
        images.append((path, image))
    pixels = width * height
    if bins > pixels:
        sys.exit(f"--bins: {bins} bins for {pixels} pixels")
    lum = [luminance(ref, 3 * j) for j in range(pixels)]
    total_lum = sum(lum)
    if not total_lum > 0.0:
        sys.exit(f"{argv[0]}: a black reference")
    order = sorted(range(pixels), key=lambda j: lum[j])
    films = [mse(im, ref, range(pixels)) for _, im in images]
    print("bin luminance        light  " + "  ".join(f"{os.path.basename(p):>24}" for p, _ in images))
    for b in range(bins):
        js = order[b * pixels // bins:(b + 1) * pixels // bins]
        share = sum(lum[j] for j in js) / total_lum
        cells = []
        for (_, im), film in zip(images, films):
            err = mse(im, ref, js)
            part = 100 * err * len(js) / (film * pixels) if film else 0
            cells.append(f"{err:.3e} ({part:5.1f}%)")
        print(f"{b:3d} {lum[js[0]]:.4f}-{lum[js[-1]]:.4f} {100 * share:5.1f}%  " +
              "  ".join(f"{c:>24}" for c in cells))
    print("all" + " " * 22 + "  ".join(f"{f:>24.3e}" for f in films))


if __name__ == "__main__":
    main(sys.argv[1:])
