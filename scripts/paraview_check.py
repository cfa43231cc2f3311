# Opens a pfdm fit.pvd in ParaView (pvpython) the way a user would and
# checks what ParaView itself reads: one time step per frame, the point
# arrays u, v and twist_deg, and a surface that moves over time.  With
# --screenshots PREFIX it also renders the first and last frame coloured by
# twist to PREFIX_first.png and PREFIX_last.png, for a look by eye.  With
# --legacy PREFIX it saves the first frame through ParaView's own legacy
# VTK writer (VTK 9: file version 5.1) as PREFIX_ascii.vtk and
# PREFIX_binary.vtk, for pfdm mesh-points to read back.
#
#   pvpython --force-offscreen-rendering scripts/paraview_check.py \
#       out/fit/fit.pvd 5 [--screenshots out/fit/paraview]
#
# Exit 0 when every check holds, 1 with one line on stderr otherwise.
import argparse
import sys

from paraview import simple, servermanager


def fail(message):
    sys.stderr.write("paraview_check: " + message + "\n")
    sys.exit(1)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("pvd")
    parser.add_argument("frames", type=int)
    parser.add_argument("--screenshots", default="")
    parser.add_argument("--legacy", default="")
    args = parser.parse_args()

    reader = simple.PVDReader(FileName=args.pvd)
    times = list(reader.TimestepValues)
    if len(times) != args.frames:
        fail("%s: %d time steps, expected %d" % (args.pvd, len(times), args.frames))
    arrays = set(reader.PointData.keys())
    for name in ("u", "v", "twist_deg"):
        if name not in arrays:
            fail("%s: no point array '%s' (has %s)" % (args.pvd, name, sorted(arrays)))

    bounds, twist_ranges = [], []
    for time in times:
        reader.UpdatePipeline(time)
        data = servermanager.Fetch(reader)
        if data.GetNumberOfPoints() == 0 or data.GetNumberOfPolys() == 0:
            fail("%s: time %g has no surface" % (args.pvd, time))
        bounds.append(data.GetBounds())
        twist_ranges.append(data.GetPointData().GetArray("twist_deg").GetRange())
    # Systole shrinks the cavity: the last frame's box is smaller than the
    # first's along every axis, and twist appears after frame 0.
    first, last = bounds[0], bounds[-1]
    for axis in range(3):
        if last[2 * axis + 1] - last[2 * axis] >= first[2 * axis + 1] - first[2 * axis]:
            fail("%s: the surface does not shrink along axis %d over time" % (args.pvd, axis))
    if twist_ranges[0] != (0.0, 0.0):
        fail("%s: frame 0 has twist %s" % (args.pvd, twist_ranges[0]))
    if max(abs(x) for x in twist_ranges[-1]) < 1.0:
        fail("%s: no twist on the last frame" % args.pvd)
    print("%s: %d time steps, arrays u v twist_deg, box %.1f -> %.1f mm along z, "
          "last frame twist %.1f..%.1f deg"
          % (args.pvd, len(times), first[5] - first[4], last[5] - last[4],
             twist_ranges[-1][0], twist_ranges[-1][1]))

    if args.legacy:
        reader.UpdatePipeline(times[0])
        for file_type in ("Ascii", "Binary"):
            simple.SaveData("%s_%s.vtk" % (args.legacy, file_type.lower()),
                            proxy=reader, FileType=file_type)

    if args.screenshots:
        view = simple.CreateView("RenderView")
        view.ViewSize = [800, 800]
        display = simple.Show(reader, view)
        simple.ColorBy(display, ("POINTS", "twist_deg"))
        lut = simple.GetColorTransferFunction("twist_deg")
        lut.RescaleTransferFunction(min(r[0] for r in twist_ranges),
                                    max(r[1] for r in twist_ranges))
        display.SetScalarBarVisibility(view, True)
        view.CameraPosition = [250.0, -250.0, 120.0]
        view.CameraViewUp = [0.0, 0.0, 1.0]
        view.ViewTime = times[0]
        view.ResetCamera()  # Once: the same camera shows the shrinking.
        for label, time in (("first", times[0]), ("last", times[-1])):
            view.ViewTime = time
            simple.SaveScreenshot("%s_%s.png" % (args.screenshots, label), view)


if __name__ == "__main__":
    main()
