#!/usr/bin/env pvbatch
"""Renders a case's particles (VTK/ of particlesToVTK) to PNG with ParaView.

Run by bin/tools/renderParticles, which documents the options and finds a
way to render without a display; its options reach this script as
--times, --view, --cut, --animate, --velocityRange, --stressRange,
--size, --output and --case.

A body's type (fluid, wall, solid), dp and nDimensions are not in the VTK
files: they come from <time>/<body>/bodyProperties of the case, so the
fluid is coloured by |U|, a solid by vonMises and walls are plain grey.
"""
import argparse
import glob
import json
import math
import os
import re
import sys

import paraview.simple as pv


# The exit status of an error this script explains (the wrapper adds
# nothing to it).
explainedError = 3


def fail(message):
    print("renderParticles: error: " + message, file=sys.stderr)
    sys.exit(explainedError)


def parseArgs():
    p = argparse.ArgumentParser(prog="renderParticles.py")
    p.add_argument("--case", default=".")
    p.add_argument("--times", default="")
    p.add_argument("--view", choices=("front", "top", "iso"))
    p.add_argument("--cut", choices=("x", "y", "z"))
    p.add_argument("--animate", type=int, default=0)
    p.add_argument("--surface", action="store_true")
    p.add_argument("--velocityRange", type=float, nargs=2)
    p.add_argument("--stressRange", type=float, nargs=2)
    p.add_argument("--size", default="1600x900")
    p.add_argument("--output", default="images")
    p.add_argument("--probe", action="store_true",
                   help="render one empty frame: can this ParaView render?")
    args = p.parse_args()
    m = re.fullmatch(r"(\d+)x(\d+)", args.size)
    if not m or int(m.group(1)) < 64 or int(m.group(2)) < 64:
        fail("-size '%s': expected WxH in pixels, e.g. 1600x900" % args.size)
    args.size = [int(m.group(1)), int(m.group(2))]
    return args


# ------------------------------------------------------------- the case ---

def readEntries(path, keys):
    """Top-level 'key value;' entries of an OpenFOAM-style dictionary."""
    found = {}
    try:
        with open(path, errors="replace") as f:
            for line in f:
                m = re.match(r"\s*(\w+)\s+([^;]+);", line)
                if m and m.group(1) in keys and m.group(1) not in found:
                    found[m.group(1)] = m.group(2).strip()
    except OSError:
        pass
    return found


def timeDirs(case):
    """The case's time directories, ascending."""
    dirs = []
    for d in os.listdir(case):
        try:
            dirs.append((float(d), d))
        except ValueError:
            continue
    return [d for _, d in sorted(dirs)]


class Body:
    def __init__(self, case, series):
        self.name = os.path.basename(series)[:-len(".vtp.series")]
        with open(series) as f:
            files = json.load(f)["files"]
        if not files:
            fail("%s lists no file" % series)
        self.times = [float(e["time"]) for e in files]
        self.firstFile = os.path.join(os.path.dirname(series),
                                      files[0]["name"])
        self.reader = pv.OpenDataFile(series)
        # Fields come and go (a solid's stress is not in 0/): the last's.
        self.reader.UpdatePipeline(self.times[-1])
        self.arrays = self.reader.PointData.keys()

        props = {}
        for t in timeDirs(case):
            props = readEntries(os.path.join(case, t, self.name,
                                             "bodyProperties"),
                                ("type", "dp", "nDimensions"))
            if props:
                break
        # Without the time directories (VTK/ copied alone) the fields tell:
        # walls have a U too, but it is zero unless they move.
        moving = "U" in self.arrays and \
            self.reader.PointData["U"].GetRange(-1)[1] > 0
        self.type = props.get("type") or (
            "solid" if "vonMises" in self.arrays else
            "fluid" if moving else "wall")
        self.dp = float(props["dp"]) if "dp" in props else None
        self.nDimensions = int(props.get("nDimensions", 0))


def spacingEstimate(body):
    """Median nearest-neighbour distance of up to 500 particles: the dp of
    a body whose bodyProperties is not there."""
    from vtkmodules.vtkCommonDataModel import vtkPointLocator
    from vtkmodules.vtkCommonCore import vtkIdList
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
    r = vtkXMLPolyDataReader()
    r.SetFileName(body.firstFile)
    r.Update()
    data = r.GetOutput()
    n = data.GetNumberOfPoints()
    if n < 2:
        return None
    locator = vtkPointLocator()
    locator.SetDataSet(data)
    locator.BuildLocator()
    ids = vtkIdList()
    d = []
    for i in range(0, n, max(1, n // 500)):
        p = data.GetPoint(i)
        locator.FindClosestNPoints(2, p, ids)
        q = data.GetPoint(ids.GetId(1))
        d.append(math.dist(p, q))
    d.sort()
    return d[len(d) // 2] or None


def nearest(times, t):
    return min(times, key=lambda x: abs(x - t))


def framesOf(times, n):
    """n times spread evenly over the written times (all if fewer)."""
    if n >= len(times):
        return list(times)
    if n == 1:
        return [times[-1]]
    return [times[round(i*(len(times) - 1)/(n - 1))] for i in range(n)]


def timeFormat(times):
    """'%.3f', or more decimals where the written times need them."""
    for d in range(3, 10):
        if len({"%.*f" % (d, t) for t in times}) == len(set(times)):
            return "%%.%df" % d
    return "%g"


def upAxis(case, planar):
    """Against gravity (constant/g; the solver's default: -y in 2D, -z in
    3D): the picture's up."""
    g = readEntries(os.path.join(case, "constant", "g"), ("value",))
    try:
        v = [float(x) for x in g["value"].strip("() ").split()]
        i = max(range(3), key=lambda k: abs(v[k]))
        if v[i] != 0:
            up = [0.0, 0.0, 0.0]
            up[i] = -math.copysign(1.0, v[i])
            return up
    except (KeyError, ValueError, IndexError):
        pass
    return [0.0, 1.0, 0.0] if planar else [0.0, 0.0, 1.0]


# ------------------------------------------------------------- geometry ---

def cross(a, b):
    return [a[1]*b[2] - a[2]*b[1], a[2]*b[0] - a[0]*b[2],
            a[0]*b[1] - a[1]*b[0]]


def dot(a, b):
    return sum(x*y for x, y in zip(a, b))


def unit(a):
    n = math.sqrt(dot(a, a))
    return [x/n for x in a]


def combine(*terms):
    """Sum of c*v over (c, v) pairs."""
    return [sum(c*v[k] for c, v in terms) for k in range(3)]


def viewFrame(view, up):
    """(toward the camera, view up) for a view, up being the picture's up."""
    right = [0.0, 1.0, 0.0] if abs(up[0]) > 0.5 else [1.0, 0.0, 0.0]
    front = cross(right, up)                # right x up: out of the screen
    if view == "front":
        return front, up
    if view == "top":
        return up, [-x for x in front]          # x to the right
    # iso: from the front, a little to the right and above.
    return unit(combine((1.0, front), (0.45, right), (0.6, up))), up


# ------------------------------------------------------------ rendering ---

# Debian ParaView's default font draws no '|' and brackets like
# parentheses: DejaVu Sans (fonts-dejavu-core) where it is installed.
FONT = "/usr/share/fonts/truetype/dejavu/DejaVuSans%s.ttf"


def setFont(proxy, prefix, size, bold=False):
    """Font of a text display (prefix "") or of a scalar bar's title or
    labels (prefix "Title" or "Label")."""
    setattr(proxy, prefix + "FontSize", size)
    font = FONT % ("-Bold" if bold else "")
    if os.path.isfile(font):
        setattr(proxy, prefix + "FontFamily", "File")
        setattr(proxy, prefix + "FontFile", font)
    else:
        setattr(proxy, prefix + "Bold", int(bold))


class Picture:
    """The render view with its layout: top band for the title and the
    time, bottom band for the colour bars, the particles in between."""

    def __init__(self, size, caseName, hasBars):
        self.view = pv.CreateView("RenderView")
        v = self.view
        v.ViewSize = size
        v.UseColorPaletteForBackground = 0
        v.Background = [1, 1, 1]
        v.OrientationAxesVisibility = 0
        v.CameraParallelProjection = 1
        v.UseFXAA = 1
        self.size = size
        self.top = 0.1
        self.bottom = 0.2 if hasBars else 0.04
        self.side = 0.03
        self.font = max(10, round(size[1]*0.026))
        self.title = self.text(caseName, "Upper Left Corner", True)
        self.clock = self.text("", "Upper Right Corner")

    def text(self, string, where, bold=False):
        source = pv.Text(Text=string)
        d = pv.Show(source, self.view)
        d.WindowLocation = where
        d.Color = [0, 0, 0]
        setFont(d, "", self.font, bold)
        return source

    def frame(self, bounds, toCamera, viewUp):
        """Parallel projection that fits bounds into the middle band."""
        d = unit(toCamera)
        upv = unit(combine((1.0, viewUp), (-dot(viewUp, d), d)))
        right = cross(upv, d)
        corners = [[bounds[0 + (k & 1)], bounds[2 + (k >> 1 & 1)],
                    bounds[4 + (k >> 2 & 1)]] for k in range(8)]
        xs = [dot(c, right) for c in corners]
        ys = [dot(c, upv) for c in corners]
        zs = [dot(c, d) for c in corners]
        w, h = max(xs) - min(xs), max(ys) - min(ys)
        aspect = self.size[0]/self.size[1]
        band = 1 - self.top - self.bottom
        scale = max(h/(2*band), w/(2*aspect*(1 - 2*self.side)), 1e-12)
        # The bounds' centre sits at the middle of the band, not of the
        # picture: shift the focal point down by the difference.
        yMid = self.bottom + band/2
        cx = (max(xs) + min(xs))/2
        cy = (max(ys) + min(ys))/2 - (yMid - 0.5)*2*scale
        cz = (max(zs) + min(zs))/2
        focal = combine((cx, right), (cy, upv), (cz, d))
        depth = max(zs) - min(zs) + w + h
        v = self.view
        v.CameraFocalPoint = focal
        v.CameraPosition = combine((1.0, focal), (2*depth, d))
        v.CameraViewUp = upv
        v.CameraParallelScale = scale

    def colourBar(self, lut, title, valueRange, slot, nSlots):
        """A horizontal bar under the particles, ticks at round values."""
        bar = pv.GetScalarBar(lut, self.view)
        bar.Title = title
        bar.ComponentTitle = ""
        bar.Orientation = "Horizontal"
        bar.WindowLocation = "Any Location"
        length = 0.3 if nSlots > 1 else 0.4
        gap = (1 - nSlots*length)/(nSlots + 1)
        bar.Position = [gap + slot*(length + gap), 0.035]
        bar.ScalarBarLength = length
        bar.ScalarBarThickness = max(8, round(self.size[1]*0.02))
        setFont(bar, "Title", self.font, True)
        setFont(bar, "Label", round(self.font*0.85))
        bar.TitleColor = bar.LabelColor = [0, 0, 0]
        bar.AutomaticLabelFormat = 0
        bar.LabelFormat = bar.RangeLabelFormat = "%g"
        bar.AddRangeLabels = 1
        # Round ticks between the ends, none so near an end that the labels
        # would overlap.
        lo, hi = valueRange
        step = niceStep(hi - lo)
        ticks = [k*step for k in range(math.ceil(lo/step), int(hi/step) + 1)]
        bar.UseCustomLabels = 1
        bar.CustomLabels = [t for t in ticks
                            if lo + 0.15*(hi - lo) < t < hi - 0.15*(hi - lo)]
        bar.DrawTickMarks = 1
        bar.Visibility = 1


def niceStep(span):
    """1, 2, 2.5 or 5 times a power of ten: 3 or 4 intervals over span,
    so that the labels of a bar do not crowd."""
    if span <= 0:
        return 1.0
    e = 10**math.floor(math.log10(span/5))
    return next(m*e for m in (1, 2, 2.5, 5, 10, 20) if span/(m*e) <= 4)


def autoRange(largest):
    """0 to the largest value rounded up to a tick."""
    step = niceStep(largest)
    return [0.0, math.ceil(largest/step - 1e-9)*step if largest > 0 else 1.0]


def lookupTable(name, presets, lo, hi, skip=0.0):
    """A preset's colours over [lo, hi], less its first skip fraction (a
    black low end shows no shading on spheres)."""
    lut = pv.GetColorTransferFunction(name)
    for preset in presets:
        if lut.ApplyPreset(preset, True):
            break
    lut.AutomaticRescaleRangeMode = "Never"
    if skip > 0:
        lut.RescaleTransferFunction(0.0, 1.0)
        p = [list(lut.RGBPoints[i:i + 4])
             for i in range(0, len(lut.RGBPoints), 4)]
        i = next(i for i in range(1, len(p)) if p[i][0] > skip)
        f = (skip - p[i - 1][0])/(p[i][0] - p[i - 1][0])
        first = [skip] + [a + f*(b - a)
                          for a, b in zip(p[i - 1][1:], p[i][1:])]
        lut.RGBPoints = [v for q in [first] + p[i:]
                         for v in [(q[0] - skip)/(1 - skip)] + q[1:]]
    lut.RescaleTransferFunction(lo, hi)
    pv.GetOpacityTransferFunction(name).RescaleTransferFunction(lo, hi)
    return lut


def beyondPlane(source, axis, at, toCamera):
    """The particles of source beyond the plane axis = at, seen from the
    camera (whole particles: crinkle clip, the side away from the normal)."""
    normal = [0.0, 0.0, 0.0]
    normal[axis] = math.copysign(1.0, toCamera[axis])
    origin = [0.0, 0.0, 0.0]
    origin[axis] = at
    clip = pv.Clip(Input=source, ClipType="Plane", Crinkleclip=1, Invert=1)
    clip.ClipType.Origin = origin
    clip.ClipType.Normal = normal
    return clip


def withoutNearFaces(wall, toCamera):
    """The wall less its faces on the camera's side (the front wall, a
    lid): they would hide the flow. A face is the 6 dp (at most 30 % of
    the wall's extent) next to the wall's bounds: a tank's few layers. A
    wall thinner than 6 dp along an axis (a plate) has no faces there."""
    source = wall.reader
    wall.reader.UpdatePipeline(wall.times[0])
    bounds = wall.reader.GetDataInformation().GetBounds()
    for k in range(3):
        if abs(toCamera[k]) < 0.2:
            continue
        lo, hi = bounds[2*k], bounds[2*k + 1]
        if hi - lo <= 6*wall.dp:
            continue
        depth = min(0.3*(hi - lo), 6*wall.dp)
        source = beyondPlane(source, k, hi - depth if toCamera[k] > 0
                             else lo + depth, toCamera)
    return source


def main():
    args = parseArgs()
    # ParaView's warnings (e.g. no range for a field missing at t = 0) are
    # noise here; errors still show.
    from vtkmodules.vtkCommonCore import vtkLogger
    vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_ERROR)
    if args.probe:
        v = pv.CreateView("RenderView")
        v.ViewSize = [64, 64]
        pv.Render(v)
        return

    case = os.path.abspath(args.case)
    caseName = os.path.basename(case)
    seriesFiles = sorted(glob.glob(os.path.join(case, "VTK", "*.vtp.series")))
    if not seriesFiles:
        fail("no VTK/*.vtp.series in %s: run particlesToVTK first" % case)
    # The free surface of particlesToVTK -freeSurface is not a body (a
    # body of that name has a bodyProperties; particlesToVTK refuses the
    # surface then).
    surfaceSeries = os.path.join(case, "VTK", "freeSurface.vtp.series")
    hasSurface = surfaceSeries in seriesFiles and not any(
        os.path.isfile(os.path.join(case, t, "freeSurface", "bodyProperties"))
        for t in timeDirs(case))
    if hasSurface:
        seriesFiles.remove(surfaceSeries)
    if args.surface and not hasSurface:
        fail("-surface: no VTK/freeSurface.vtp.series in %s: run "
             "particlesToVTK -freeSurface first" % case)
    bodies = [Body(case, s) for s in seriesFiles]
    allTimes = sorted({t for b in bodies for t in b.times})
    fmt = timeFormat(allTimes)

    # The times: each request snaps to the nearest written time.
    snapshots = []
    for word in args.times.split():
        try:
            t = float(word)
        except ValueError:
            fail("-times: '%s' is not a number" % word)
        snapped = nearest(allTimes, t)
        print("renderParticles: time %s -> written time %g" % (word, snapped))
        if snapped not in snapshots:
            snapshots.append(snapped)
    if not snapshots and args.animate <= 0:
        snapshots = [allTimes[-1]]
        print("renderParticles: no -times: the latest time, %g" % allTimes[-1])
    frames = framesOf(allTimes, args.animate) if args.animate > 0 else []
    rendered = sorted(set(snapshots) | set(frames))
    if args.surface:
        # ParaView holds a series at its nearest time: a surface written
        # for other times would be drawn over these particles unsaid.
        with open(surfaceSeries) as f:
            surfaceTimes = [float(e["time"]) for e in json.load(f)["files"]]
        missing = [t for t in rendered if not any(
            abs(t - s) <= 1e-9*max(1.0, abs(t)) for s in surfaceTimes)]
        if missing:
            fail("-surface: VTK/freeSurface.vtp.series has no surface at t = "
                 "%s of the %d times to draw (it has %d, %s to %s): run "
                 "particlesToVTK -freeSurface for them (without -time: all)"
                 % (" ".join(fmt % t for t in missing[:6])
                    + (" ..." if len(missing) > 6 else ""), len(rendered),
                    len(surfaceTimes), fmt % min(surfaceTimes),
                    fmt % max(surfaceTimes)))

    for b in bodies:
        if b.dp is None:
            b.dp = spacingEstimate(b) or 0.01
            print("renderParticles: %s: no bodyProperties, dp estimated as %g"
                  % (b.name, b.dp))
    # 2D: every body says so, or every particle has z = 0.
    planar = all(b.nDimensions == 2 for b in bodies) or all(
        b.nDimensions == 0 and b.reader.GetDataInformation().GetBounds()[4:6]
        == (0.0, 0.0) for b in bodies)
    view = args.view or ("front" if planar else "iso")
    if planar and view != "front":
        print("renderParticles: 2D case: front view (-view %s ignored)" % view)
        view = "front"

    # One pass over the rendered times: the bounds that the camera keeps
    # and the colour ranges that every frame shares (the largest values).
    bounds = [math.inf, -math.inf]*3
    uMax = sMax = 0.0
    fluids = [b for b in bodies if b.type == "fluid" and "U" in b.arrays]
    solids = [b for b in bodies
              if b.type == "solid" and "vonMises" in b.arrays]
    for b in bodies:
        field = {"fluid": "U", "solid": "vonMises"}.get(b.type)
        if field and field not in b.arrays:
            print("renderParticles: %s has no %s in its VTK files (written "
                  "with particlesToVTK -fields?): drawn in one colour"
                  % (b.name, field))
    for t in sorted(set(rendered) | {allTimes[0]}):
        for b in bodies:
            b.reader.UpdatePipeline(t)
            bb = b.reader.GetDataInformation().GetBounds()
            for k in range(3):
                bounds[2*k] = min(bounds[2*k], bb[2*k] - b.dp/2)
                bounds[2*k + 1] = max(bounds[2*k + 1], bb[2*k + 1] + b.dp/2)
            u, s = b.reader.PointData["U"], b.reader.PointData["vonMises"]
            if b in fluids and u:
                uMax = max(uMax, u.GetRange(-1)[1])
            if b in solids and s:
                sMax = max(sMax, s.GetRange()[1])
    uRange = args.velocityRange or autoRange(uMax)
    sRange = args.stressRange or autoRange(sMax)

    pic = Picture(args.size, caseName, bool(fluids or solids))
    toCamera, viewUp = viewFrame(view, upAxis(case, planar))
    pic.frame(bounds, toCamera, viewUp)
    cut = None
    if args.cut and planar:
        print("renderParticles: 2D case: -cut %s ignored" % args.cut)
    elif args.cut:
        axis = "xyz".index(args.cut)
        if abs(toCamera[axis]) < 0.2:
            fail("-cut %s: the %s axis lies across the %s view; cut along an "
                 "axis that points toward the camera" % (args.cut, args.cut, view))
        cut = (axis, (bounds[2*axis] + bounds[2*axis + 1])/2)
        print("renderParticles: fluids and solids cut at %s = %g, the half "
              "away from the camera shown" % (args.cut, cut[1]))

    luts = {"U": lookupTable("U", ("Turbo", "Jet"), *uRange),
            "vonMises": lookupTable("vonMises", ("Inferno (matplotlib)",
                                                 "Black-Body Radiation"),
                                    *sRange, skip=0.0 if planar else 0.15)}
    # U+2223 for the bars of |U|: VTK takes '|' for a column separator.
    bars = ([(luts["U"], "\u2223U\u2223 [m/s]", uRange)] if fluids else []) + \
        ([(luts["vonMises"], "von Mises [Pa]", sRange)] if solids else [])
    for b in bodies:
        if args.surface and b.type == "fluid" and not planar:
            continue        # the surface stands for it
        source = b.reader
        if b.type == "wall" and not planar:
            source = withoutNearFaces(b, toCamera)
        elif cut:
            source = beyondPlane(source, *cut, toCamera)
        d = pv.Show(source, pic.view)
        d.SetRepresentationType("Point Gaussian")
        d.ShaderPreset = "Plain circle" if planar else "Sphere"
        # Touching spheres in 3D; in 2D discs a little larger, so that the
        # fluid reads as a continuum.
        d.GaussianRadius = (0.7 if planar else 0.5)*b.dp
        d.ScaleByArray = 0
        # The plain colour shows where the field is missing (a solid's
        # stress at t = 0): the colour of the range's low end.
        d.AmbientColor = d.DiffuseColor = (
            [0.72, 0.72, 0.72] if b.type == "wall" else
            luts["vonMises"].RGBPoints[1:4] if b in solids else
            luts["U"].RGBPoints[1:4] if b in fluids else [0.3, 0.5, 0.8])
        if b in fluids:
            pv.ColorBy(d, ("POINTS", "U", "Magnitude"))
        elif b in solids:
            pv.ColorBy(d, ("POINTS", "vonMises"))
        else:
            d.ColorArrayName = ["POINTS", ""]
    if args.surface:
        # The water's surface coloured as its particles would be; in 2D its
        # outline over the particles.
        source = pv.OpenDataFile(surfaceSeries)
        if cut:
            source = beyondPlane(source, *cut, toCamera)
        d = pv.Show(source, pic.view)
        d.SetRepresentationType("Surface")
        d.LineWidth = 3
        d.AmbientColor = d.DiffuseColor = [0.1, 0.2, 0.5] if planar else \
            luts["U"].RGBPoints[1:4]
        if fluids and not planar:
            pv.ColorBy(d, ("POINTS", "U", "Magnitude"))
        else:
            d.ColorArrayName = ["POINTS", ""]
    for slot, (lut, title, valueRange) in enumerate(bars):
        # After ColorBy, which fits a table to the data it sees first.
        lut.RescaleTransferFunction(*valueRange)
        pic.colourBar(lut, title, valueRange, slot, len(bars))

    output = os.path.join(case, args.output)     # relative to the case
    os.makedirs(output, exist_ok=True)

    def render(t, png):
        pic.view.ViewTime = t
        pic.clock.Text = "t = " + (fmt % t) + " s"
        pv.SaveScreenshot(png, pic.view, ImageResolution=args.size)

    for t in snapshots:
        png = os.path.join(output, "%s_t%g.png" % (caseName, t))
        render(t, png)
        print("renderParticles: t = %g -> %s" % (t, png))
    if frames:
        frameDir = os.path.join(output, "animation")
        os.makedirs(frameDir, exist_ok=True)
        for old in glob.glob(os.path.join(frameDir, "frame_*.png")):
            os.remove(old)
        for i, t in enumerate(frames):
            render(t, os.path.join(frameDir, "frame_%04d.png" % i))
        print("renderParticles: %d animation frames (t = %g to %g) -> %s/"
              "frame_0000.png ..." % (len(frames), frames[0], frames[-1],
                                      frameDir))
    for lut, title, (lo, hi) in bars:
        print("renderParticles: colour range of %s: %g to %g"
              % (title.replace("\u2223", "|"), lo, hi))


if __name__ == "__main__":
    main()
