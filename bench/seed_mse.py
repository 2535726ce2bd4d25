"""Error of each method from its renders at several seeds, without a reference.

    python3 bench/seed_mse.py DIR SCENE METHOD [METHOD ...]

Reads DIR/SCENE-METHOD-*.pfm: one render per seed, all of one film. The
renders of an unbiased method at independent seeds scatter about the true
image, so a pixel's sample variance over them (n - 1 in the denominator) is
the expected squared error of one render there, and its mean over the film
and the channels is one render's MSE. Block means (8x8 and 32x32 pixels, as
bench/error_time.sh) give the block MSEs the same way. Each method's figures
are printed with their ratios to the first METHOD's. A bias would not show:
the render tests check that (doc/testing.md). Pure Python.
"""
import glob
import sys

from ideal_mse import read_pfm

BLOCKS = (1, 8, 32)


def block_means(width, height, rgb, side):
    """Per side x side block (whole blocks only) and channel, the mean."""
    out = []
    for by in range(height // side):
        for bx in range(width // side):
            for c in range(3):
                s = 0.0
                for y in range(by * side, (by + 1) * side):
                    row = 3 * y * width
                    s += sum(rgb[row + 3 * x + c] for x in range(bx * side, (bx + 1) * side))
                out.append(s / (side * side))
    return out


def seed_variance(images):
    """Mean over values of their sample variance across the images."""
    n = len(images)
    total = 0.0
    for values in zip(*images):
        mean = sum(values) / n
        total += sum((v - mean) ** 2 for v in values) / (n - 1)
    return total / len(images[0])


def method_mse(paths):
    films = [read_pfm(p) for p in paths]
    width, height = films[0][0], films[0][1]
    if any(f[:2] != (width, height) for f in films):
        sys.exit(f"{paths[0]}: the renders' films differ in size")
    out = []
    for side in BLOCKS:
        if side > width or side > height:
            out.append(None)
            continue
        out.append(seed_variance([block_means(width, height, f[2], side) if side > 1 else f[2]
                                  for f in films]))
    return out


def main(argv):
    if len(argv) < 4:
        sys.exit(__doc__.strip().splitlines()[2].strip())
    directory, scene, methods = argv[1], argv[2], argv[3:]
    results = []
    for m in methods:
        paths = sorted(glob.glob(f"{directory}/{scene}-{m}-*.pfm"))
        if len(paths) < 2:
            sys.exit(f"{directory}/{scene}-{m}-*.pfm: {len(paths)} render(s), need 2 or more")
        results.append((m, len(paths), method_mse(paths)))
    base = results[0][2]
    names = ["mse", "block8", "block32"]
    for m, n, r in results:
        cells = []
        for name, v, b in zip(names, r, base):
            if v is None:
                cells.append(f"{name} -")
            else:
                ratio = f"{v / b:.3f}" if b else "-"
                cells.append(f"{name} {v:.4g} ({ratio})")
        print(f"{scene} {m}: {n} seeds, " + ", ".join(cells))


if __name__ == "__main__":
    main(sys.argv)
