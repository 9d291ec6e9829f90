"""Geodesy against independent libraries, and the two ENU->ECEF rotations."""

from __future__ import annotations

import numpy as np
import pymap3d
import pyproj
import pytest

from registration import _codegen
from registration.core import frames

WGS84_A = 6378137.0
WGS84_B = WGS84_A * (1 - 1 / 298.257223563)


def _random_geodetic(n, seed):
    rng = np.random.default_rng(seed)
    lat = np.arcsin(rng.uniform(-1, 1, n))  # uniform over the sphere
    lon = rng.uniform(-np.pi, np.pi, n)
    alt = rng.uniform(-500.0, 1.0e5, n)
    lat[:4] = [np.pi / 2, -np.pi / 2, 0.0, 0.0]
    lon[:4] = [0.0, np.pi, np.pi, -np.pi]
    return lat, lon, alt


def test_geodetic2ecef_matches_pyproj_to_a_millimetre():
    lat, lon, alt = _random_geodetic(10_000, 0)
    ours = frames.geodetic2ecef(lat, lon, alt)
    tr = pyproj.Transformer.from_crs("EPSG:4979", "EPSG:4978", always_xy=True)
    x, y, z = tr.transform(np.degrees(lon), np.degrees(lat), alt)
    err = np.abs(ours - np.stack([x, y, z], axis=1)).max()
    assert err <= 1e-3, f"max difference to pyproj {err} m"


def test_ecef2geodetic_inverts_pyproj_from_the_trench_to_low_orbit():
    """The generated inverse, at 10 000 points made by pyproj's forward transform with heights
    -12 km to 1000 km (poles and the antimeridian included), returns the points' geodetic
    coordinates to 1e-12 rad and 1e-6 m. pyproj's own inverse is less exact up there (a single
    Bowring step: 9e-10 rad and 8 mm at 1000 km), so against it the bound is its accuracy."""
    lat, lon, _ = _random_geodetic(10_000, 3)
    alt = np.random.default_rng(4).uniform(-12e3, 1e6, lat.size)
    tr = pyproj.Transformer.from_crs("EPSG:4979", "EPSG:4978", always_xy=True)
    p_ecef = np.stack(tr.transform(np.degrees(lon), np.degrees(lat), alt), axis=1)
    got_lat, got_lon, got_alt = frames.ecef2geodetic(p_ecef)
    off_pole = np.abs(np.cos(lat)) > 1e-9  # longitude is undefined at the poles
    assert np.abs(got_lat - lat).max() < 1e-12
    assert np.abs(np.angle(np.exp(1j * (got_lon - lon)))[off_pole]).max() < 1e-12
    assert np.abs(got_alt - alt).max() < 1e-6
    back = pyproj.Transformer.from_crs("EPSG:4978", "EPSG:4979", always_xy=True)
    ref_lon, ref_lat, ref_alt = back.transform(p_ecef[:, 0], p_ecef[:, 1], p_ecef[:, 2])
    assert np.abs(got_lat - np.radians(ref_lat)).max() < 2e-9 and np.abs(got_alt - ref_alt).max() < 0.02
    with pytest.raises(ValueError, match="within 100 km of the earth's centre"):
        frames.ecef2geodetic([[1.0, 2.0, 3.0]])
    with pytest.raises(ValueError, match=r"shape \(N, 3\)"):
        frames.ecef2geodetic([1.0, 2.0])


def test_geodetic2ecef_matches_pymap3d_to_a_millimetre():
    lat, lon, alt = _random_geodetic(10_000, 1)
    ours = frames.geodetic2ecef(lat, lon, alt)
    x, y, z = pymap3d.geodetic2ecef(lat, lon, alt, deg=False)
    err = np.abs(ours - np.stack([x, y, z], axis=1)).max()
    assert err <= 1e-3, f"max difference to pymap3d {err} m"


def test_manifest_constants_are_wgs84():
    c = _codegen.manifest()["constants"]
    assert c["wgs84_a_m"] == WGS84_A
    assert c["wgs84_b_m"] == pytest.approx(WGS84_B, rel=1e-15)


def test_standard_rotation_is_orthonormal_with_det_one():
    lat, lon, _ = _random_geodetic(2_000, 2)
    R = frames.enu2ecef_rotation(lat, lon)
    eye = np.broadcast_to(np.eye(3), R.shape)
    assert np.abs(R @ R.transpose(0, 2, 1) - eye).max() < 1e-14
    assert np.abs(np.linalg.det(R) - 1).max() < 1e-14


def test_standard_rotation_matches_pymap3d_enu2ecef():
    """R_ecef_enu @ v_enu equals pymap3d's enu2uvw (an independent implementation)."""
    lat, lon, _ = _random_geodetic(500, 3)
    R = frames.enu2ecef_rotation(lat, lon)
    v = np.random.default_rng(4).normal(size=(500, 3))
    ours = np.einsum("nij,nj->ni", R, v)
    u, vv, w = pymap3d.enu2uvw(v[:, 0], v[:, 1], v[:, 2], lat, lon, deg=False)
    assert np.abs(ours - np.stack([u, vv, w], axis=1)).max() < 1e-13


def test_up_axis_is_the_geodetic_normal():
    """The third column of R_ecef_enu is the ellipsoid normal: d(ECEF)/d(alt)."""
    lat, lon, alt = _random_geodetic(200, 5)
    R = frames.enu2ecef_rotation(lat, lon)
    d = frames.geodetic2ecef(lat, lon, alt + 1.0) - frames.geodetic2ecef(lat, lon, alt)
    assert np.abs(d - R[:, :, 2]).max() < 1e-7


def test_paper_rotation_is_standard_at_tilted_latitude():
    """Eq. (4) as printed = standard T at psi with tan psi = (a/b)^2 tan B (Wang et al. 2011, eq. (4))."""
    lat, lon, _ = _random_geodetic(2_000, 6)
    lat = np.clip(lat, -1.5, 1.5)
    psi = np.arctan((WGS84_A / WGS84_B) ** 2 * np.tan(lat))
    paper = frames.enu2ecef_rotation(lat, lon, variant="paper")
    standard_at_psi = frames.enu2ecef_rotation(psi, lon)
    assert np.abs(paper - standard_at_psi).max() < 1e-14
    # ... and it differs from the standard rotation at B: ~0.13 deg tilt at 20 deg N
    tilt = np.arccos(
        np.clip(np.einsum("ni,ni->n", paper[:, :, 2], frames.enu2ecef_rotation(lat, lon)[:, :, 2]), -1, 1)
    )
    at20 = np.argmin(np.abs(lat - np.radians(20)))
    assert tilt.max() > 1e-3
    assert np.degrees(tilt[at20]) == pytest.approx(np.degrees(abs(psi[at20] - lat[at20])), abs=1e-9)
