"""Pictures of a run's XDMF files as ParaView shows them.

Usage (Debian packages paraview, python3-paraview, xvfb):
    xvfb-run -a pvbatch scripts/render_xdmf.py OUT_DIR

Writes, in OUT_DIR:
  paraview_fields.png     the last step of fields.xdmf: the deformed shape
                          (displacement_m, magnified) coloured by sigma1_MPa
  paraview_envelopes.png  envelopes.xdmf coloured by max_principal_MPa
  paraview_modes.png      modes.xdmf: mode 1 (warped) coloured by its
                          magnitude
  paraview_joints.png     contact joints: joint_envelope.xdmf, the joint
                          faces coloured by their largest opening [cm]
Each panel is the same recipe a user follows by hand in ParaView: open the
file (Xdmf3 reader), Warp By Vector on displacement_m (or a mode), colour
by a field.
"""
import glob
import os
import sys

from paraview.simple import (ColorBy, GetActiveViewOrCreate,
                             GetColorTransferFunction, Hide, Render,
                             ResetCamera, SaveScreenshot, Show,
                             WarpByVector, Xdmf3ReaderS)


def view_2d_or_3d(view, bounds):
    """Looks at the section from +z (2D) or the dam from downstream (3D)."""
    flat = abs(bounds[5] - bounds[4]) < 1e-9
    cx = 0.5 * (bounds[0] + bounds[1])
    cy = 0.5 * (bounds[2] + bounds[3])
    cz = 0.5 * (bounds[4] + bounds[5])
    size = max(bounds[1] - bounds[0], bounds[3] - bounds[2],
               bounds[5] - bounds[4])
    view.CameraFocalPoint = [cx, cy, cz]
    if flat:
        view.CameraPosition = [cx, cy, cz + 3 * size]
        view.CameraViewUp = [0, 1, 0]
    else:
        view.CameraPosition = [cx + 1.2 * size, cy + 2.0 * size,
                               cz + 1.0 * size]
        view.CameraViewUp = [0, 0, 1]
    view.CameraParallelProjection = 1 if flat else 0


def picture(source, field, association, title, png, warp=None, scale=1.0):
    view = GetActiveViewOrCreate("RenderView")
    view.OrientationAxesVisibility = 1
    shown = source
    if warp:
        shown = WarpByVector(Input=source)
        shown.Vectors = ["POINTS", warp]
        shown.ScaleFactor = scale
    display = Show(shown, view)
    ColorBy(display, (association, field))
    display.SetScalarBarVisibility(view, True)
    lut = GetColorTransferFunction(field)
    lut.ApplyPreset("Cool to Warm", True)
    bar = lut.GetScalarBar(view) if hasattr(lut, "GetScalarBar") else None
    if bar is not None:
        bar.Title = title
    source.UpdatePipeline()
    view_2d_or_3d(view, shown.GetDataInformation().GetBounds())
    ResetCamera(view)
    Render(view)
    SaveScreenshot(png, view, ImageResolution=[1200, 900])
    Hide(shown, view)
    print(png)


def warp_scale(reader, vector):
    """A magnification that makes the largest displacement 5% of the
    model's size."""
    info = reader.GetDataInformation()
    b = info.GetBounds()
    size = max(b[1] - b[0], b[3] - b[2], b[5] - b[4])
    arr = reader.PointData[vector]
    umax = max(abs(r) for r in arr.GetRange(-1))
    return 0.05 * size / umax if umax > 0 else 1.0


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    out = sys.argv[1]
    fields = os.path.join(out, "fields.xdmf")
    if os.path.exists(fields):
        r = Xdmf3ReaderS(FileName=[fields])
        r.UpdatePipeline(max(r.TimestepValues) if r.TimestepValues else 0)
        view = GetActiveViewOrCreate("RenderView")
        if r.TimestepValues:
            view.ViewTime = max(r.TimestepValues)
        picture(r, "sigma1_MPa", "CELLS", "sigma1 [MPa], deformed",
                os.path.join(out, "paraview_fields.png"), "displacement_m",
                warp_scale(r, "displacement_m"))
    # Single-grid files: file, field, its association, title, picture.
    for name, field, association, title, png in (
            ("envelopes.xdmf", "max_principal_MPa", "CELLS",
             "envelope of sigma1 [MPa]", "paraview_envelopes.png"),
            ("joint_envelope.xdmf", "max_opening_cm", "POINTS",
             "largest joint opening [cm]", "paraview_joints.png")):
        path = os.path.join(out, name)
        if os.path.exists(path):
            picture(Xdmf3ReaderS(FileName=[path]), field, association, title,
                    os.path.join(out, png))
    modes = os.path.join(out, "modes.xdmf")
    if os.path.exists(modes):
        r = Xdmf3ReaderS(FileName=[modes])
        r.UpdatePipeline()
        names = sorted(n for n in r.PointData.keys() if n.startswith("mode_"))
        if names:
            picture(r, names[0], "POINTS", names[0],
                    os.path.join(out, "paraview_modes.png"), names[0],
                    warp_scale(r, names[0]))
    return 0


if __name__ == "__main__":
    status = main()
    # Leave before the render windows are torn down: under Xvfb that
    # teardown reports a harmless GLX error after the pictures are saved.
    sys.stdout.flush()
    os._exit(status)
