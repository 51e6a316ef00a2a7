# SPDX-License-Identifier: Apache-2.0
# Writes one benchmark scene, from one description, as a toroid YAML scene
# or as the equivalent POV-Ray 3.7 scene.
#
#   awk -v scene=NAME -v format=yaml|pov -v mode=render|mask -v depth=D -v sturm=0|1 -f scenes.awk
#
# scene: tori25 | scatter2000 | glass3 | far. mode=mask: the tori alone, flat
# white on black (silhouettes). depth: toroid's --max-depth (bounces);
# POV-Ray's max_trace_level counts the eye ray too, so it gets depth + 1.
#
# Conventions. Both use a left-handed world with y up, and the same camera
# model (field of view across the width, look-at with an up vector), so
# points map unchanged. toroid's torus lies in its xy-plane (axis z),
# POV-Ray's in its xz-plane (axis y): the POV torus first gets the matrix Q,
# (x, y, z) -> (x, -z, y), which lays it in the xy-plane, then the same
# object-to-world matrix M as toroid's transform list. M is written
# transposed, since POV-Ray multiplies row vectors.

function rand01() {  # Park-Miller, exact in doubles: same numbers in any awk
  seed = (seed * 16807) % 2147483647
  return seed / 2147483647
}

# Shortest of %.15g and %.17g that reads back as the same double.
function fmt(x,    s) { s = sprintf("%.15g", x); return (s + 0 == x) ? s : sprintf("%.17g", x) }

function camera(w, h, fov, fx, fy, fz, tx, ty, tz, ux, uy, uz,    dx, dy, dz, d, u, cx, cy, cz) {
  cam_w = w; cam_h = h; cam_fov = fov
  # The book's view_transform does not normalise its `left` vector, which
  # has the length s = sin(angle between view direction and up): the
  # picture is the one of a field of view widened to 2 atan(tan(fov/2) / s).
  # POV-Ray gets that angle.
  dx = tx - fx; dy = ty - fy; dz = tz - fz; d = sqrt(dx * dx + dy * dy + dz * dz)
  u = sqrt(ux * ux + uy * uy + uz * uz)
  cx = dy * uz - dz * uy; cy = dz * ux - dx * uz; cz = dx * uy - dy * ux
  cam_pov_angle = 2 * atan2(sin(fov / 2) / cos(fov / 2) / (sqrt(cx * cx + cy * cy + cz * cz) / (d * u)), 1) * 180 / pi
  cam_from = fmt(fx) ", " fmt(fy) ", " fmt(fz)
  cam_to = fmt(tx) ", " fmt(ty) ", " fmt(tz)
  cam_up = fmt(ux) ", " fmt(uy) ", " fmt(uz)
}

function light(x, y, z, i) { nl++; lx[nl] = x; ly[nl] = y; lz[nl] = z; li[nl] = i }

# A material: colour, ambient, diffuse, specular, shininess, reflective,
# transparency, refractive index.
function material(name, r, g, b, amb, dif, spec, shin, refl, transp, ior) {
  nm++; mname[nm] = name
  mr[name] = r; mg[name] = g; mb[name] = b; mamb[name] = amb; mdif[name] = dif; mspec[name] = spec
  mshin[name] = shin; mrefl[name] = refl; mtransp[name] = transp; mior[name] = ior
}

# A floor: the plane y = 0, plain or checkered (unit squares, colours a/b).
function floor_plane(checker, mat_a, mat_b) { has_floor = 1; floor_checker = checker; floor_a = mat_a; floor_b = mat_b }

# A torus: radii, material, shadow flag, then rotate-x ax, rotate-y ay,
# translate (x, y, z), in that order.
function torus(R, r, mat, shadow, ax, ay, x, y, z) {
  nt++; tR[nt] = R; tr[nt] = r; tmat[nt] = mat; tshadow[nt] = shadow
  tax[nt] = ax; tay[nt] = ay; tx_[nt] = x; ty_[nt] = y; tz_[nt] = z
}

# The tori's materials: three colours, for tori numbered i, colour(i).
function torus_colours() {
  material("red", 0.85, 0.25, 0.2, 0.1, 0.7, 0.4, 60, 0, 0, 1)
  material("gold", 0.9, 0.7, 0.25, 0.1, 0.7, 0.4, 60, 0, 0, 1)
  material("teal", 0.2, 0.65, 0.6, 0.1, 0.7, 0.4, 60, 0, 0, 1)
}
function colour(i) { return i % 3 == 0 ? "red" : i % 3 == 1 ? "gold" : "teal" }

function build(    i, j, x, z, a, R, r, col) {
  seed = 20240601
  if (scene == "tori25") {
    camera(1280, 720, 0.9, 0, 5.5, -11, 0, 0.5, 1.5, 0, 1, 0)
    light(-8, 12, -10, 0.9); light(10, 8, -6, 0.4)
    material("floor_a", 0.9, 0.9, 0.9, 0.1, 0.8, 0.2, 50, 0.4, 0, 1)
    material("floor_b", 0.15, 0.2, 0.3, 0.1, 0.8, 0.2, 50, 0.4, 0, 1)
    torus_colours()
    floor_plane(1, "floor_a", "floor_b")
    for (i = 0; i < 5; i++)
      for (j = 0; j < 5; j++) {
        x = (i - 2) * 2.2; z = (j - 2) * 2.2 + 2
        col = colour(i + j)
        if ((i + j) % 2 == 0) torus(0.7, 0.22, col, 1, pi / 2, 0.3 * i, x, 0.22, z)      # lying flat
        else torus(0.7, 0.22, col, 1, 0, 0.35 * j + 0.2 * i, x, 0.92, z)                 # standing
      }
  } else if (scene == "scatter2000") {
    camera(1280, 720, 0.9, 0, 8, -22, 0, 3, 2, 0, 1, 0)
    light(-8, 12, -10, 0.9); light(10, 8, -6, 0.4)
    material("floor_a", 0.8, 0.8, 0.75, 0.1, 0.8, 0, 50, 0, 0, 1)
    torus_colours()
    floor_plane(0, "floor_a", "floor_a")
    for (i = 0; i < 2000; i++) {
      col = colour(i)
      x = -12 + 24 * rand01(); a = 0.6 + 6.4 * rand01(); z = -6 + 16 * rand01()
      torus(0.35, 0.1, col, 1, 2 * pi * rand01(), 2 * pi * rand01(), x, a, z)
    }
  } else if (scene == "glass3") {
    camera(960, 540, 0.8, 0, 3, -8, 0, 1, 0, 0, 1, 0)
    light(-6, 10, -8, 1)
    material("floor_a", 0.9, 0.9, 0.9, 0.1, 0.8, 0, 50, 0, 0, 1)
    material("floor_b", 0.2, 0.3, 0.5, 0.1, 0.8, 0, 50, 0, 0, 1)
    material("glass", 0.05, 0.05, 0.05, 0, 0.1, 1, 300, 0.9, 0.9, 1.5)
    floor_plane(1, "floor_a", "floor_b")
    # Glass casts no shadow in either renderer (POV-Ray would filter light
    # through it, toroid would block it): no_shadow / shadow: false.
    torus(1, 0.35, "glass", 0, 0, 0.4, -2.3, 1.35, 0.5)
    torus(1, 0.35, "glass", 0, pi / 2, 0, 0, 0.35, 0)
    torus(1, 0.35, "glass", 0, 0.5, -0.6, 2.3, 1.4, 0.8)
  } else if (scene == "far") {
    # About 4,470 units away, 1 degree across: 78 units of view.
    camera(1280, 720, pi / 180, 0, 2000, -4000, 0, 6, 0, 0, 1, 0)
    light(-3000, 5000, -4000, 1)
    material("floor_a", 0.8, 0.8, 0.75, 0.1, 0.8, 0, 50, 0, 0, 1)
    torus_colours()
    floor_plane(0, "floor_a", "floor_a")
    for (i = 0; i < 7; i++) {
      R = 6 + 3 * rand01(); r = R / (30 + 70 * rand01())  # tubes 1/30 to 1/100 of the ring
      col = colour(i)
      torus(R, r, col, 1, 2 * pi * rand01(), 2 * pi * rand01(), -28 + 56 * rand01(), R + 1 + 4 * rand01(), -10 + 20 * rand01())
    }
  } else {
    print "scenes.awk: unknown scene '" scene "' (tori25, scatter2000, glass3, far)" > "/dev/stderr"
    exit 2
  }
}

function yaml_material(name) {
  if (mode == "mask") return "{ color: [1, 1, 1], ambient: 1, diffuse: 0, specular: 0 }"
  return name
}

function write_yaml(    i, n) {
  print "# Generated by bench/vs-povray/scenes.awk: scene " scene ", " mode "."
  print "- add: camera"
  print "  width: " cam_w; print "  height: " cam_h; print "  field-of-view: " fmt(cam_fov)
  print "  from: [" cam_from "]"; print "  to: [" cam_to "]"; print "  up: [" cam_up "]"
  if (mode == "mask") {
    print "- add: light"; print "  at: [" fmt(lx[1]) ", " fmt(ly[1]) ", " fmt(lz[1]) "]"; print "  intensity: [1, 1, 1]"
  } else {
    for (i = 1; i <= nl; i++) {
      print "- add: light"; print "  at: [" fmt(lx[i]) ", " fmt(ly[i]) ", " fmt(lz[i]) "]"
      print "  intensity: [" fmt(li[i]) ", " fmt(li[i]) ", " fmt(li[i]) "]"
    }
    for (i = 1; i <= nm; i++) {
      n = mname[i]
      if (n ~ /^floor/ && floor_checker) continue
      print "- define: " n; print "  value:"
      print "    color: [" fmt(mr[n]) ", " fmt(mg[n]) ", " fmt(mb[n]) "]"
      print "    ambient: " fmt(mamb[n]); print "    diffuse: " fmt(mdif[n]); print "    specular: " fmt(mspec[n])
      print "    shininess: " fmt(mshin[n]); print "    reflective: " fmt(mrefl[n])
      print "    transparency: " fmt(mtransp[n]); print "    refractive-index: " fmt(mior[n])
    }
    if (has_floor) {
      print "- add: plane"
      if (floor_checker) {
        n = floor_a
        print "  material:"
        print "    pattern:"; print "      type: checkers"
        print "      colors: [[" fmt(mr[floor_a]) ", " fmt(mg[floor_a]) ", " fmt(mb[floor_a]) "], [" fmt(mr[floor_b]) ", " fmt(mg[floor_b]) ", " fmt(mb[floor_b]) "]]"
        print "    ambient: " fmt(mamb[n]); print "    diffuse: " fmt(mdif[n]); print "    specular: " fmt(mspec[n])
        print "    shininess: " fmt(mshin[n]); print "    reflective: " fmt(mrefl[n])
      } else {
        print "  material: " floor_a
      }
    }
  }
  for (i = 1; i <= nt; i++) {
    print "- add: torus"; print "  major: " fmt(tR[i]); print "  minor: " fmt(tr[i])
    print "  material: " yaml_material(tmat[i])
    if (!tshadow[i] && mode != "mask") print "  shadow: false"
    print "  transform:"
    print "    - [rotate-x, " fmt(tax[i]) "]"; print "    - [rotate-y, " fmt(tay[i]) "]"
    print "    - [translate, " fmt(tx_[i]) ", " fmt(ty_[i]) ", " fmt(tz_[i]) "]"
  }
}

function pov_finish(n) {
  if (mode == "mask") return "pigment { rgb 1 } finish { ambient 1 diffuse 0 }"
  s = sprintf("finish { ambient %s diffuse %s phong %s phong_size %s", fmt(mamb[n]), fmt(mdif[n]), fmt(mspec[n]), fmt(mshin[n]))
  if (mrefl[n] > 0) s = s " reflection { " fmt(mrefl[n]) " }"
  return s " }"
}

function pov_material(n) {
  if (mode == "mask") return pov_finish(n)
  if (mtransp[n] > 0)
    return sprintf("pigment { rgbt <%s, %s, %s, %s> } %s interior { ior %s }", fmt(mr[n]), fmt(mg[n]), fmt(mb[n]), fmt(mtransp[n]), pov_finish(n), fmt(mior[n]))
  return sprintf("pigment { rgb <%s, %s, %s> } %s", fmt(mr[n]), fmt(mg[n]), fmt(mb[n]), pov_finish(n))
}

function write_pov(    i, ca, sa, cb, sb, L) {
  print "// Generated by bench/vs-povray/scenes.awk: scene " scene ", " mode (sturm ? ", sturm" : "") "."
  print "#version 3.7;"
  printf "global_settings { assumed_gamma 1.0 max_trace_level %d adc_bailout 0 }\n", depth + 1
  printf "camera { perspective location <%s> sky <%s> up y right x*%d/%d angle %s look_at <%s> }\n", cam_from, cam_up, cam_w, cam_h, fmt(cam_pov_angle), cam_to
  if (mode == "mask") {
    printf "light_source { <%s, %s, %s> color rgb 1 }\n", fmt(lx[1]), fmt(ly[1]), fmt(lz[1])
  } else {
    for (i = 1; i <= nl; i++) printf "light_source { <%s, %s, %s> color rgb %s }\n", fmt(lx[i]), fmt(ly[i]), fmt(lz[i]), fmt(li[i])
    if (has_floor) {
      if (floor_checker)
        printf "plane { y, 0 pigment { checker rgb <%s, %s, %s> rgb <%s, %s, %s> } %s }\n", fmt(mr[floor_a]), fmt(mg[floor_a]), fmt(mb[floor_a]), fmt(mr[floor_b]), fmt(mg[floor_b]), fmt(mb[floor_b]), pov_finish(floor_a)
      else
        printf "plane { y, 0 %s }\n", pov_material(floor_a)
    }
  }
  for (i = 1; i <= nt; i++) {
    ca = cos(tax[i]); sa = sin(tax[i]); cb = cos(tay[i]); sb = sin(tay[i])
    # L = rotation_y(ay) * rotation_x(ax), as in the book's matrices.
    L[0,0] = cb; L[0,1] = sb * sa; L[0,2] = sb * ca
    L[1,0] = 0;  L[1,1] = ca;      L[1,2] = -sa
    L[2,0] = -sb; L[2,1] = cb * sa; L[2,2] = cb * ca
    printf "torus { %s, %s%s matrix <1, 0, 0, 0, 0, 1, 0, -1, 0, 0, 0, 0> matrix <%s, %s, %s, %s, %s, %s, %s, %s, %s, %s, %s, %s> %s%s }\n", \
      fmt(tR[i]), fmt(tr[i]), sturm ? " sturm" : "", \
      fmt(L[0,0]), fmt(L[1,0]), fmt(L[2,0]), fmt(L[0,1]), fmt(L[1,1]), fmt(L[2,1]), fmt(L[0,2]), fmt(L[1,2]), fmt(L[2,2]), \
      fmt(tx_[i]), fmt(ty_[i]), fmt(tz_[i]), pov_material(tmat[i]), (!tshadow[i] && mode != "mask") ? " no_shadow" : ""
  }
}

BEGIN {
  pi = 3.14159265358979323846
  if (depth == "") depth = 5
  if (mode == "") mode = "render"
  build()
  if (format == "yaml") write_yaml()
  else if (format == "pov") write_pov()
  else { print "scenes.awk: format must be yaml or pov" > "/dev/stderr"; exit 2 }
}
