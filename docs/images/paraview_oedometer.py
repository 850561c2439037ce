"""ParaView screenshot of an oedometer run at its last snapshot (docs/pictures.md).

    xvfb-run -a pvpython docs/images/paraview_oedometer.py out/oedometer/result.xmf docs/images/paraview_oedometer.png

Left: the spheres at their true size (Point Gaussian, Sphere shader, radius array), the
half y < 0 cut away, coloured by their speed. Right: the contacts of the slab |y| < 10 mm,
those above 100 N coloured by their normal force, the rest light grey. Grey: the walls. The
image is then reduced to 256 colours (Pillow) to stay small.
"""
import sys
from paraview.simple import (XDMFReader, ExtractBlock, Clip, Threshold, Show, ColorBy,
                             GetColorTransferFunction, CreateView, CreateLayout,
                             AssignViewToLayout, SaveScreenshot, GetScalarBar)

xmf, png = sys.argv[1], sys.argv[2]
reader = XDMFReader(FileNames=[xmf])
reader.UpdatePipelineInformation()
t = reader.TimestepValues[-1]


def block(name):
    b = ExtractBlock(Input=reader)
    b.Selectors = ['/Root/' + name]
    return b


def view():
    v = CreateView('RenderView')
    v.ViewTime = t
    v.OrientationAxesVisibility = 0
    v.UseColorPaletteForBackground = 0
    v.Background = [1, 1, 1]
    v.CameraPosition = [0.06, -0.25, 0.13]
    v.CameraFocalPoint = [0.012, 0, 0.03]
    v.CameraViewUp = [0, 0, 1]
    v.CameraViewAngle = 29
    return v


def walls_in(v):
    back = Clip(Input=block('walls'))   # a clip keeps the side its normal points away from
    back.ClipType = 'Plane'
    back.ClipType.Origin = [0, 0, 0]
    back.ClipType.Normal = [0, -1, 0]
    w = Show(back, v)
    w.Representation = 'Wireframe'
    w.AmbientColor = w.DiffuseColor = [0.6, 0.6, 0.6]
    ColorBy(w, None)
    w.Opacity = 0.35


def bar(v, lut, title, fmt):
    b = GetScalarBar(lut, v)
    b.Title = title
    b.ComponentTitle = ''
    b.TitleColor = b.LabelColor = [0, 0, 0]
    b.WindowLocation = 'Any Location'
    b.Position = [0.80, 0.1]
    b.ScalarBarLength = 0.4
    b.TitleFontSize = 13
    b.LabelFontSize = 12
    b.RangeLabelFormat = fmt
    b.Visibility = 1


layout = CreateLayout('oedometer')
left, right = view(), view()
AssignViewToLayout(view=left, layout=layout, hint=0)
layout.SplitHorizontal(0, 0.5)
AssignViewToLayout(view=right, layout=layout, hint=2)

half = Clip(Input=block('particles'))
half.ClipType = 'Plane'
half.ClipType.Origin = [0, 0, 0]
half.ClipType.Normal = [0, -1, 0]
half.Crinkleclip = 1
s = Show(half, left)
s.SetRepresentationType('Point Gaussian')
s.ShaderPreset = 'Sphere'
s.ScaleByArray = 1
s.SetScaleArray = ['POINTS', 'radius']
s.UseScaleFunction = 0
s.GaussianRadius = 1
ColorBy(s, ('POINTS', 'velocity', 'Magnitude'))
speed = GetColorTransferFunction('velocity')
speed.ApplyPreset('Viridis (matplotlib)', True)
speed.AutomaticRescaleRangeMode = 'Never'
speed.RescaleTransferFunction(0.0, 0.0084)   # the piston's speed, 500 mm/min
bar(left, speed, 'speed (m/s)', '%.4f')
walls_in(left)

slab = Clip(Input=block('contacts'))
slab.ClipType = 'Plane'
slab.ClipType.Origin = [0, -0.01, 0]
slab.ClipType.Normal = [0, -1, 0]
slab.Crinkleclip = 1
slab2 = Clip(Input=slab)
slab2.ClipType = 'Plane'
slab2.ClipType.Origin = [0, 0.01, 0]
slab2.ClipType.Normal = [0, 1, 0]
slab2.Crinkleclip = 1
weak = Show(slab2, right)
ColorBy(weak, None)
weak.AmbientColor = weak.DiffuseColor = [0.75, 0.75, 0.75]
weak.LineWidth = 1
strong = Threshold(Input=slab2)
strong.Scalars = ['CELLS', 'normal_force']
strong.LowerThreshold = 100.0
strong.UpperThreshold = 1e9
st = Show(strong, right)
ColorBy(st, ('CELLS', 'normal_force'))
force = GetColorTransferFunction('normal_force')
force.ApplyPreset('Inferno (matplotlib)', True)
force.AutomaticRescaleRangeMode = 'Never'
force.RescaleTransferFunction(100.0, 250.0)
st.LineWidth = 3
bar(right, force, 'normal force (N)', '%.0f')
walls_in(right)

SaveScreenshot(png, layout, ImageResolution=[1000, 520], FontScaling='Do not scale fonts',
               TransparentBackground=0)

from PIL import Image  # python3-pil
Image.open(png).convert('RGB').quantize(colors=256).save(png, optimize=True)
