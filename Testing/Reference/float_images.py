"""Helpers the reference scripts share: reading the portable float maps (linear RGB, rows
bottom to top) that the references and the study images are stored as, and sRGB encoding."""
import numpy as np


def read_pfm(path):
    """A PFM as an H x W x 3 float64 array, rows bottom to top as stored."""
    with open(path, "rb") as f:
        if f.readline().strip() != b"PF":
            raise ValueError(path + " is not an RGB portable float map")
        w, h = map(int, f.readline().split())
        if float(f.readline()) >= 0.0:
            raise ValueError(path + " is not little endian")
        return np.frombuffer(f.read(), "<f4").reshape(h, w, 3).astype(np.float64)


def srgb_encode(linear):
    """The sRGB transfer function of linear values in [0, 1] (numbers or arrays)."""
    c = np.asarray(linear, dtype=np.float64)
    return np.where(c <= 0.0031308, 12.92 * c, 1.055 * np.maximum(c, 0.0) ** (1.0 / 2.4) - 0.055)
