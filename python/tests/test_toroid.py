# SPDX-License-Identifier: Apache-2.0
"""Tests of the Python module toroid (python/toroid_module.cpp).

ctest runs each class as Python.<class less "Test">, with PYTHONPATH at the
built module and TOROID_FAMILIES_FILE at the C++ answers that
toroid_python_families writes. By hand, from the repository root:

    PYTHONPATH=build/python python3 python/tests/test_toroid.py -v

(CppAgreementTest then needs TOROID_FAMILIES_FILE=build/python/families.bin
or is skipped.)
"""

import math
import os
import struct
import sys
import threading
import time
import unittest

import numpy as np

import toroid

INF = math.inf
NAN = math.nan
MAJOR, MINOR = 1.0, 0.25
# Along the x axis through the hole: four roots, exact in binary.
ORIGIN = [-5.0, 0.0, 0.0]
DIRECTION = [1.0, 0.0, 0.0]
ROOTS = [3.75, 4.25, 5.75, 6.25]
# Rays the C API answers with no roots (and no nearest root).
BAD_RAYS = [
    ([NAN, 0.0, 0.0], DIRECTION),
    ([-5.0, INF, 0.0], DIRECTION),
    (ORIGIN, [-INF, 0.0, 0.0]),
    (ORIGIN, [1.0, NAN, 0.0]),
    (ORIGIN, [0.0, 0.0, 0.0]),
    (ORIGIN, [-0.0, 0.0, -0.0]),
]


def bits(a):
    """The float64 values of a as integers: == on them compares bit for bit."""
    return np.ascontiguousarray(a, dtype=np.float64).view(np.uint64)


def rays(n):
    """n different rays, all hitting the torus (a fan through the hole)."""
    z = np.linspace(-0.2, 0.2, n) if n > 1 else np.zeros(n)
    origins = np.tile(ORIGIN, (n, 1))
    directions = np.stack([np.full(n, 5.0), np.zeros(n), -z], axis=1)
    origins[:, 2] = z
    return origins, directions


class EntryPointChecks:
    """Bad input through one entry point: a clear error naming the argument,
    or the documented value; never a crash. A subclass sets `function`,
    `arrays` (its (N, 3) arguments) and good() (valid keyword arguments)."""

    function = None
    arrays = ()

    def good(self, n=3):
        raise NotImplementedError

    def call(self, **changes):
        kwargs = self.good()
        kwargs.update(changes)
        return type(self).function(**kwargs)

    def assert_error(self, error, name, **changes):
        """The call with `changes` raises `error`, whose message starts with
        the argument's name; returns the message."""
        with self.assertRaises(error, msg=f"{changes!r}") as caught:
            self.call(**changes)
        message = str(caught.exception)
        self.assertRegex(message, rf"^{name}\b", f"{changes!r}")
        return message

    def results(self, value):
        """The result arrays of a call, as a tuple."""
        return value if isinstance(value, tuple) else (value,)

    def test_bad_radii_raise_value_error(self):
        for name in ("major", "minor"):
            for value in (0.0, -0.0, -1.0, NAN, INF, -INF, 0):
                message = self.assert_error(ValueError, name, **{name: value})
                self.assertIn("finite and > 0", message)
                self.assertIn(repr(float(value)), message)

    def test_radii_of_other_types(self):
        for name in ("major", "minor"):
            for value in ("1.0", 1 + 0j, np.complex128(1.0), None, object(), np.array(["1"])):
                self.assert_error(TypeError, name, **{name: value})
            for value in ([1.0], np.ones((1, 1))):
                self.assertIn("shape (1", self.assert_error(ValueError, name, **{name: value}))
        expected = [bits(a) for a in self.results(self.call())]
        for major, minor in ((1, MINOR), (np.float32(1.0), np.float32(0.25)), (np.int64(1), np.array(0.25)),
                             (np.array(1.0, dtype=np.float16), MINOR)):
            got = self.results(self.call(major=major, minor=minor))
            for g, e in zip(got, expected):
                self.assertTrue(np.array_equal(bits(g), e), (major, minor))

    def test_arrays_of_other_dtypes_raise_type_error(self):
        n = self.good()[self.arrays[0]].shape[0]
        for name in self.arrays:
            for value in (np.ones((n, 3), dtype=np.complex128), np.full((n, 3), "1.0"), np.full((n, 3), None),
                          np.ones((n, 3), dtype=np.longdouble), [[1, 2, "3"]] * n, "abc", None,
                          np.zeros((n, 3), dtype="datetime64[s]")):
                message = self.assert_error(TypeError, name, **{name: value})
                self.assertIn("dtype", message)

    def test_arrays_of_other_shapes_raise_value_error(self):
        for name in self.arrays:
            for value, shape in ((np.ones(3), "(3,)"), (np.ones((2, 2)), "(2, 2)"), (np.ones((2, 4)), "(2, 4)"),
                                 (np.ones((2, 3, 1)), "(2, 3, 1)"), (np.ones(0), "(0,)"), (5.0, "()"),
                                 ([], "(0,)"), ([[1.0, 2.0, 3.0], [1.0, 2.0]], None)):
                message = self.assert_error(ValueError, name, **{name: value})
                if shape is not None:
                    self.assertIn(f"shape {shape}", message)

    def test_array_likes_give_the_float64_answers(self):
        kwargs = self.good()
        expected = [bits(a) for a in self.results(self.call())]
        base = {name: kwargs[name] for name in self.arrays}
        variants = {
            "lists": {k: v.tolist() for k, v in base.items()},
            "tuples": {k: tuple(map(tuple, v.tolist())) for k, v in base.items()},
            "Fortran order": {k: np.asfortranarray(v) for k, v in base.items()},
            "strided": {k: np.repeat(v, 2, axis=0)[::2] for k, v in base.items()},
            "big-endian": {k: v.astype(">f8") for k, v in base.items()},
            "read-only": {k: v.copy() for k, v in base.items()},
            "unaligned": {},
        }
        for k, v in base.items():
            variants["read-only"][k].flags.writeable = False
            buffer = np.zeros(v.size * 8 + 1, dtype=np.uint8)
            unaligned = np.frombuffer(buffer.data, dtype=np.float64, count=v.size, offset=1).reshape(v.shape)
            unaligned[...] = v
            self.assertFalse(unaligned.flags.aligned)
            variants["unaligned"][k] = unaligned
        for what, changes in variants.items():
            got = self.results(self.call(**changes))
            self.assertEqual(len(got), len(expected))
            for g, e in zip(got, expected):
                self.assertTrue(np.array_equal(bits(g), e), what)
        # Other dtypes: against float64 arrays of the same values.
        for dtype, values in ((np.float32, lambda v: v), (np.float16, lambda v: v), (np.int64, np.round),
                              (np.int8, np.round), (np.uint16, np.abs)):
            same = {k: values(v).astype(dtype) for k, v in base.items()}
            as_float64 = {k: v.astype(np.float64) for k, v in same.items()}
            for g, e in zip(self.results(self.call(**same)), self.results(self.call(**as_float64))):
                self.assertTrue(np.array_equal(bits(g), bits(e)), dtype)

    def test_no_rays(self):
        kwargs = self.good(n=0)
        got = self.results(self.call(**kwargs))
        full = self.results(self.call())
        for g, f in zip(got, full):
            self.assertEqual(g.shape, (0,) + f.shape[1:])
            self.assertEqual(g.dtype, f.dtype)
        for g in self.results(self.call(**{name: np.empty((0, 3), dtype=np.int32) for name in self.arrays})):
            self.assertEqual(g.shape[0], 0)

    def test_results_are_fresh_c_contiguous_arrays(self):
        kwargs = self.good()
        first = self.results(self.call(**kwargs))
        second = self.results(self.call(**kwargs))
        for a, b in zip(first, second):
            self.assertIsInstance(a, np.ndarray)
            self.assertTrue(a.flags.c_contiguous and a.flags.writeable and a.flags.owndata)
            self.assertFalse(np.shares_memory(a, b))
            for name in self.arrays:
                self.assertFalse(np.shares_memory(a, kwargs[name]))

    def test_the_inputs_are_left_alone(self):
        kwargs = self.good()
        before = {name: kwargs[name].copy() for name in self.arrays}
        for a in self.results(self.call(**kwargs)):
            a[...] = 7
        for name in self.arrays:
            self.assertTrue(np.array_equal(bits(kwargs[name]), bits(before[name])))

    def test_keyword_and_positional_arguments(self):
        kwargs = self.good()
        positional = self.results(type(self).function(*kwargs.values()))
        for p, k in zip(positional, self.results(self.call())):
            self.assertTrue(np.array_equal(bits(p), bits(k)))
        with self.assertRaises(TypeError):
            type(self).function(**kwargs, colour=1)


class RayChecks(EntryPointChecks):
    """EntryPointChecks for a function of rays: origins and directions."""

    arrays = ("origins", "directions")

    def test_mismatched_lengths_raise_value_error(self):
        origins, directions = rays(4)
        message = self.assert_error(ValueError, "directions", origins=origins, directions=directions[:3])
        self.assertIn("(3, 3)", message)
        self.assertIn("(4, 3)", message)
        self.assert_error(ValueError, "directions", origins=origins[:0], directions=directions)


class IntersectTorusTest(RayChecks, unittest.TestCase):
    function = toroid.intersect_torus

    def good(self, n=3):
        origins, directions = rays(n)
        return {"major": MAJOR, "minor": MINOR, "origins": origins, "directions": directions}

    def test_four_roots_through_the_hole(self):
        counts, roots = toroid.intersect_torus(MAJOR, MINOR, [ORIGIN], [DIRECTION])
        self.assertEqual(counts.dtype, np.int32)
        self.assertEqual(roots.dtype, np.float64)
        self.assertEqual(counts.tolist(), [4])
        self.assertEqual(roots.tolist(), [ROOTS])

    def test_negative_roots_and_direction_length(self):
        counts, roots = toroid.intersect_torus(MAJOR, MINOR, [[0.0, 0.0, 0.0], ORIGIN], [DIRECTION, [4.0, 0.0, 0.0]])
        self.assertEqual(counts.tolist(), [4, 4])
        self.assertEqual(roots[0].tolist(), [-1.25, -0.75, 0.75, 1.25])
        self.assertEqual(roots[1].tolist(), [t / 4 for t in ROOTS])

    def test_rows_beyond_the_count_are_nan(self):
        # Through the tube only (2 roots), and past the torus (none).
        counts, roots = toroid.intersect_torus(MAJOR, MINOR, [[1.0, 0.0, -5.0], [-5.0, 0.0, 3.0]],
                                               [[0.0, 0.0, 1.0], DIRECTION])
        self.assertEqual(counts.tolist(), [2, 0])
        self.assertEqual(roots[0, :2].tolist(), [4.75, 5.25])
        self.assertTrue(np.isnan(roots[0, 2:]).all())
        self.assertTrue(np.isnan(roots[1]).all())

    def test_spindle_torus_inner_sheet(self):
        counts, roots = toroid.intersect_torus(1.0, 1.5, [ORIGIN], [DIRECTION])
        self.assertEqual(counts.tolist(), [4])
        self.assertEqual(roots.tolist(), [[2.5, 4.5, 5.5, 7.5]])

    def test_tangent_ray_has_double_roots(self):
        counts, roots = toroid.intersect_torus(MAJOR, MINOR, [[-5.0, 0.0, MINOR]], [DIRECTION])
        self.assertEqual(counts.tolist(), [4])
        np.testing.assert_allclose(roots[0], [4.0, 4.0, 6.0, 6.0], rtol=1e-6)

    def test_bad_rays_have_no_roots(self):
        origins = [o for o, _ in BAD_RAYS] + [ORIGIN]
        directions = [d for _, d in BAD_RAYS] + [DIRECTION]
        counts, roots = toroid.intersect_torus(MAJOR, MINOR, origins, directions)
        self.assertEqual(counts.tolist(), [0] * len(BAD_RAYS) + [4])
        self.assertTrue(np.isnan(roots[:-1]).all())
        self.assertEqual(roots[-1].tolist(), ROOTS)


class NearestTest(RayChecks, unittest.TestCase):
    function = toroid.nearest

    def good(self, n=3):
        origins, directions = rays(n)
        return {"major": MAJOR, "minor": MINOR, "origins": origins, "directions": directions, "t_min": 0.0,
                "t_max": INF}

    def nearest1(self, **kwargs):
        t = toroid.nearest(MAJOR, MINOR, [kwargs.pop("origin", ORIGIN)], [kwargs.pop("direction", DIRECTION)],
                           **kwargs)
        self.assertEqual(t.shape, (1,))
        self.assertEqual(t.dtype, np.float64)
        return t[0]

    def test_default_window_is_zero_to_inf(self):
        self.assertEqual(self.nearest1(), 3.75)
        self.assertEqual(self.nearest1(origin=[0.0, 0.0, 0.0]), 0.75)
        self.assertEqual(self.nearest1(origin=[0.0, 0.0, 0.0], t_min=-INF), -1.25)
        self.assertEqual(self.nearest1(origin=[10.0, 0.0, 0.0]), INF)

    def test_the_window_is_open(self):
        self.assertEqual(self.nearest1(t_min=3.75), 4.25)
        self.assertEqual(self.nearest1(t_min=np.nextafter(3.75, 0)), 3.75)
        self.assertEqual(self.nearest1(t_max=3.75), INF)
        self.assertEqual(self.nearest1(t_max=np.nextafter(3.75, 4)), 3.75)
        self.assertEqual(self.nearest1(t_min=4.0, t_max=6.0), 4.25)
        self.assertEqual(self.nearest1(t_min=6.25, t_max=INF), INF)
        self.assertEqual(self.nearest1(t_min=3.75, t_max=3.75), INF)
        self.assertEqual(self.nearest1(t_min=INF, t_max=INF), INF)
        self.assertEqual(self.nearest1(t_min=-INF, t_max=-INF), INF)

    def test_misses_and_bad_rays_give_inf(self):
        origins = [o for o, _ in BAD_RAYS] + [ORIGIN, [-5.0, 0.0, 3.0]]
        directions = [d for _, d in BAD_RAYS] + [DIRECTION, DIRECTION]
        t = toroid.nearest(MAJOR, MINOR, origins, directions, t_min=-INF)
        self.assertEqual(t.tolist(), [INF] * len(BAD_RAYS) + [3.75, INF])

    def test_bad_windows_raise_value_error(self):
        self.assert_error(ValueError, "t_min", t_min=NAN)
        self.assert_error(ValueError, "t_max", t_max=NAN)
        self.assert_error(ValueError, "t_max", t_max=np.float32("nan"))
        message = self.assert_error(ValueError, "t_min", t_min=2.0, t_max=1.0)
        self.assertIn("t_max", message)
        self.assert_error(ValueError, "t_min", t_min=INF, t_max=-INF)
        for name in ("t_min", "t_max"):
            self.assert_error(TypeError, name, **{name: "0"})
            self.assert_error(TypeError, name, **{name: 1j})
            self.assert_error(ValueError, name, **{name: [0.0, 1.0]})

    def test_window_of_other_number_types(self):
        for t_min, t_max in ((4, 6), (np.float32(4.0), np.int16(6)), (np.array(4.0), 6.0)):
            self.assertEqual(self.nearest1(t_min=t_min, t_max=t_max), 4.25)


class NormalTest(EntryPointChecks, unittest.TestCase):
    function = toroid.normal
    arrays = ("points",)

    def good(self, n=3):
        phi = np.linspace(0.0, 2.0 * np.pi, n, endpoint=False)
        points = np.stack([MAJOR + MINOR * np.cos(phi), np.zeros(n), MINOR * np.sin(phi)], axis=1)
        return {"major": MAJOR, "minor": MINOR, "points": points}

    def test_known_normals(self):
        points = [[1.25, 0.0, 0.0], [0.75, 0.0, 0.0], [1.0, 0.0, 0.25], [0.0, -1.0, -0.25], [0.0, 2.0, 0.0]]
        want = [[1.0, 0.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]]
        self.assertEqual(toroid.normal(MAJOR, MINOR, points).tolist(), want)

    def test_normals_are_unit(self):
        rng = np.random.default_rng(7)
        u, v = rng.uniform(0, 2 * np.pi, (2, 1000))
        points = np.stack([(MAJOR + MINOR * np.cos(v)) * np.cos(u), (MAJOR + MINOR * np.cos(v)) * np.sin(u),
                           MINOR * np.sin(v)], axis=1)
        normals = toroid.normal(MAJOR, MINOR, points)
        self.assertEqual(normals.shape, (1000, 3))
        np.testing.assert_allclose(np.linalg.norm(normals, axis=1), 1.0, rtol=1e-15)
        want = np.stack([np.cos(v) * np.cos(u), np.cos(v) * np.sin(u), np.sin(v)], axis=1)
        np.testing.assert_allclose(normals, want, atol=1e-12)

    def test_spindle_axis_points(self):
        z = math.sqrt(1.5 ** 2 - 1.0)
        normals = toroid.normal(1.0, 1.5, [[0.0, 0.0, z], [0.0, 0.0, -z]])
        self.assertEqual(normals.tolist(), [[0.0, 0.0, 1.0], [0.0, 0.0, -1.0]])

    def test_points_without_a_normal_give_nan(self):
        points = [[NAN, 0.0, 0.0], [0.0, INF, 0.0], [0.0, 0.0, -INF], [1.0, 0.0, 0.0], [0.0, -1.0, 0.0],
                  [1.25, 0.0, 0.0]]
        normals = toroid.normal(MAJOR, MINOR, points)
        self.assertTrue(np.isnan(normals[:-1]).all())
        self.assertEqual(normals[-1].tolist(), [1.0, 0.0, 0.0])


class ModuleTest(unittest.TestCase):
    def test_version(self):
        self.assertRegex(toroid.__version__, r"^\d+\.\d+\.\d+$")
        expected = os.environ.get("TOROID_EXPECTED_VERSION")
        if expected is None:
            self.skipTest("TOROID_EXPECTED_VERSION is not set (ctest sets it)")
        self.assertEqual(toroid.__version__, expected)

    def test_docstrings(self):
        self.assertIn("ray-torus", toroid.__doc__)
        signatures = {
            toroid.intersect_torus: "intersect_torus(major, minor, origins, directions) -> (counts, roots)",
            toroid.nearest: "nearest(major, minor, origins, directions, t_min=0.0, t_max=inf) -> t",
            toroid.normal: "normal(major, minor, points) -> normals",
        }
        for function, signature in signatures.items():
            self.assertTrue(function.__doc__.startswith(signature + "\n"), function.__doc__)
            for word in ("(N, 3)", "ValueError", "TypeError", "NaN"):
                self.assertIn(word, function.__doc__, function.__name__)


def read_arrays(path):
    """The named arrays of a file that toroid_python_families wrote."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"TOROIDPY":
        raise ValueError(f"{path}: not a toroid_python_families file")
    arrays, pos = {}, 8
    while pos < len(data):
        (length,) = struct.unpack_from("<I", data, pos)
        name = data[pos + 4:pos + 4 + length].decode()
        pos += 4 + length
        dtype = data[pos:pos + 4].rstrip(b"\0").decode()
        (ndim,) = struct.unpack_from("<I", data, pos + 4)
        shape = struct.unpack_from(f"<{ndim}Q", data, pos + 8)
        pos += 8 + 8 * ndim
        count = math.prod(shape)
        arrays[name] = np.frombuffer(data, dtype=dtype, count=count, offset=pos).reshape(shape).copy()
        pos += arrays[name].nbytes
    return arrays


def radius_runs(radii):
    """(start, stop) of each run of consecutive rows with the same radii."""
    change = np.flatnonzero(np.any(radii[1:] != radii[:-1], axis=1)) + 1
    bounds = [0, *change.tolist(), len(radii)]
    return list(zip(bounds[:-1], bounds[1:]))


class CppAgreementTest(unittest.TestCase):
    """The module answers exactly what the C++ calls answer (checked.h) on the
    rays of every accuracy family and on bad rays: the file holds the rays
    and the C++ answers, bit for bit."""

    @classmethod
    def setUpClass(cls):
        path = os.environ.get("TOROID_FAMILIES_FILE")
        if path is None:
            raise unittest.SkipTest("TOROID_FAMILIES_FILE is not set (ctest sets it)")
        cls.a = read_arrays(path)
        cls.names = bytes(cls.a["family_names"]).decode().split("\n")[:-1]

    def where(self, ray):
        a = self.a
        return (f"ray {ray} of family {self.names[a['family'][ray]]}: radii {a['radii'][ray].tolist()}, "
                f"origin {a['origins'][ray].tolist()}, direction {a['directions'][ray].tolist()}")

    def assert_same_bits(self, got, want, rows, what, where=None):
        where = where or self.where
        same = bits(got) == bits(want)
        if same.ndim > 1:
            same = same.all(axis=tuple(range(1, same.ndim)))
        if not same.all():
            i = int(np.flatnonzero(~same)[0])
            hex_bits = lambda v: [f"{b:#018x}" for b in np.atleast_1d(bits(v)).tolist()]
            self.fail(f"{what}: {np.count_nonzero(~same)} rows differ; first, {where(rows[i])}: "
                      f"got {got[i].tolist()} (bits {hex_bits(got[i])}), "
                      f"C++ {want[i].tolist()} (bits {hex_bits(want[i])})")

    def test_the_file_covers_the_families(self):
        a = self.a
        self.assertGreater(len(self.names), 10)
        self.assertEqual(self.names[-1], "bad-rays")
        self.assertEqual(set(a["family"].tolist()), set(range(len(self.names))))
        self.assertGreater(len(a["counts"]), 20000)
        self.assertGreater(a["counts"].sum(), len(a["counts"]))
        self.assertGreater(np.isfinite(a["nearest"]).sum(), len(a["counts"]))
        self.assertTrue((a["counts"][a["family"] == len(self.names) - 1][:-3] == 0).all())

    def test_intersect_torus(self):
        a = self.a
        n = len(a["counts"])
        counts = np.full(n, -9, dtype=np.int32)
        roots = np.zeros((n, 4))
        for start, stop in radius_runs(a["radii"]):
            major, minor = a["radii"][start]
            counts[start:stop], roots[start:stop] = toroid.intersect_torus(
                major, minor, a["origins"][start:stop], a["directions"][start:stop])
        rows = np.arange(n)
        if not np.array_equal(counts, a["counts"]):
            i = int(np.flatnonzero(counts != a["counts"])[0])
            self.fail(f"counts differ; first, {self.where(i)}: got {counts[i]}, C++ {a['counts'][i]}")
        self.assert_same_bits(roots, a["roots"], rows, "roots (NaN padding included)")

    def test_nearest_in_fixed_windows(self):
        a = self.a
        n = len(a["counts"])
        for w, (t_min, t_max) in enumerate(a["windows"]):
            t = np.zeros(n)
            for start, stop in radius_runs(a["radii"]):
                major, minor = a["radii"][start]
                o, d = a["origins"][start:stop], a["directions"][start:stop]
                # The first window is the default one: called without it.
                t[start:stop] = (toroid.nearest(major, minor, o, d) if w == 0 else
                                 toroid.nearest(major, minor, o, d, t_min=t_min, t_max=t_max))
            self.assert_same_bits(t, a["nearest"][w], np.arange(n), f"nearest in ({t_min}, {t_max})")

    def test_nearest_in_windows_bounded_by_a_root(self):
        a = self.a
        rays = a["root_ray"]
        after, before = np.zeros(len(rays)), np.zeros(len(rays))
        for j, (ray, t) in enumerate(zip(rays, a["root_t"])):
            major, minor = a["radii"][ray]
            o, d = a["origins"][ray:ray + 1], a["directions"][ray:ray + 1]
            after[j] = toroid.nearest(major, minor, o, d, t_min=t)[0]
            before[j] = toroid.nearest(major, minor, o, d, t_min=-INF, t_max=t)[0]
        self.assertGreater(len(rays), len(a["counts"]))
        self.assert_same_bits(after, a["nearest_after_root"], rays, "nearest after a root")
        self.assert_same_bits(before, a["nearest_before_root"], rays, "nearest before a root")

    def test_normal(self):
        a = self.a
        rays = a["point_ray"]
        normals = np.zeros_like(a["points"])
        for start, stop in radius_runs(a["radii"][rays]):
            major, minor = a["radii"][rays[start]]
            normals[start:stop] = toroid.normal(major, minor, a["points"][start:stop])
        self.assertTrue(np.isnan(a["normals"]).any())
        where = lambda j: f"point {a['points'][j].tolist()}, radii {a['radii'][rays[j]].tolist()}"
        self.assert_same_bits(normals, a["normals"], np.arange(len(rays)), "normals", where)


class GilTest(unittest.TestCase):
    """The loops run without the GIL. With thread switching by time turned
    off, a thread keeps the GIL until it blocks or releases it; so this
    thread, spinning with the GIL, sees a worker's CPU clock advance only if
    the worker's call runs without the GIL."""

    # Of the worker's computing, that this thread must see: far more than a
    # blocked thread uses, far less than the calls below take.
    CPU_SECONDS = 0.005

    def watch(self, call):
        if not hasattr(time, "pthread_getcpuclockid"):
            self.skipTest("no per-thread CPU clocks here")
        started, finish = threading.Event(), threading.Event()
        outcome = []

        def worker():
            started.set()
            try:
                outcome.append(call())
            except BaseException as e:  # reported below, in the test's thread
                outcome.append(e)
            finish.wait()

        interval = sys.getswitchinterval()
        sys.setswitchinterval(1e6)
        thread = threading.Thread(target=worker)
        try:
            thread.start()
            started.wait()
            clock = time.pthread_getcpuclockid(thread.ident)
            start = time.clock_gettime(clock)
            seen = 0.0
            deadline = time.monotonic() + 20.0
            while seen < self.CPU_SECONDS and time.monotonic() < deadline:
                seen = time.clock_gettime(clock) - start
        finally:
            finish.set()
            thread.join()
            sys.setswitchinterval(interval)
        self.assertEqual(len(outcome), 1)
        self.assertNotIsInstance(outcome[0], BaseException)
        self.assertGreaterEqual(seen, self.CPU_SECONDS,
                                "the worker did not compute while this thread held the GIL")
        return outcome[0]

    def batch(self, n):
        """n rays from a sphere around the torus, aimed into its box. They
        are float64 and C-contiguous, so the module copies nothing (NumPy can
        release the GIL while it copies): the loop is the only place where
        the call can let this thread run."""
        rng = np.random.default_rng(3)
        origins = rng.normal(size=(n, 3))
        origins *= 3 / np.linalg.norm(origins, axis=1)[:, None]
        targets = rng.uniform(-1, 1, (n, 3)) * [MAJOR + MINOR, MAJOR + MINOR, MINOR]
        return origins, targets - origins

    def test_intersect_torus(self):
        origins, directions = self.batch(500_000)
        counts, roots = self.watch(lambda: toroid.intersect_torus(MAJOR, MINOR, origins, directions))
        self.assertEqual(roots.shape, (500_000, 4))
        self.assertGreater(counts.sum(), 500_000)

    def test_nearest(self):
        origins, directions = self.batch(500_000)
        t = self.watch(lambda: toroid.nearest(MAJOR, MINOR, origins, directions))
        self.assertGreater(np.isfinite(t).sum(), 250_000)

    def test_normal(self):
        points, _ = self.batch(1_000_000)
        normals = self.watch(lambda: toroid.normal(MAJOR, MINOR, points))
        self.assertEqual(normals.shape, (1_000_000, 3))
        self.assertFalse(np.isnan(normals).any())

    def test_threads_share_the_work(self):
        origins, directions = self.batch(50_000)
        want = toroid.nearest(MAJOR, MINOR, origins, directions)
        got = [None] * 4

        def run(k):
            got[k] = toroid.nearest(MAJOR, MINOR, origins[k::4], directions[k::4])

        threads = [threading.Thread(target=run, args=(k,)) for k in range(4)]
        for thread in threads:
            thread.start()
        for thread in threads:
            thread.join()
        for k in range(4):
            self.assertTrue(np.array_equal(bits(got[k]), bits(want[k::4])))


if __name__ == "__main__":
    unittest.main()
