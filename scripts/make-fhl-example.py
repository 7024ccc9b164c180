#!/usr/bin/python3
"""Writes the bundled "own exercise" example: scenarios/fhl/fhl-utm10n.tif, a projected GeoTIFF
(WGS 84 / UTM zone 10N, EPSG:32610) of 8 km x 8 km at 30 m posts near Fort Hunter Liggett, and
scenarios/fhl/fhl-objects.csv. Deterministic (closed-form heights, no random numbers). Needs
python3-gdal and python3-numpy (scripts/install-deps.sh). Run from the repository root:
    /usr/bin/python3 scripts/make-fhl-example.py
The terrain: rolling hills 300-420 m and a lake (bottom 270 m) in the south-east whose shore is
the 290 m contour (the scenario's water_level_m)."""
import numpy as np
from osgeo import gdal, osr

N, POST = 267, 30.0              # 267 x 267 posts, 30 m: 7,980 m a side
EAST0, NORTH0 = 656000.0, 3990000.0  # upper-left corner (UTM 10N metres)

x = np.arange(N) * POST          # metres east of the west edge
y = (N - 1 - np.arange(N)) * POST  # metres north of the south edge (row 0 = north)
X, Y = np.meshgrid(x, y)
h = 360 + 40 * np.sin(X / 900.0) * np.cos(Y / 1300.0) + 20 * np.sin((X + 2 * Y) / 2100.0)
lake = np.exp(-(((X - 6000) / 900.0) ** 2 + ((Y - 1800) / 700.0) ** 2))
h = h - 120 * lake
h = np.round(h, 2).astype(np.float32)

drv = gdal.GetDriverByName("GTiff")
ds = drv.Create("scenarios/fhl/fhl-utm10n.tif", N, N, 1, gdal.GDT_Float32, ["COMPRESS=DEFLATE", "PREDICTOR=3"])
ds.SetGeoTransform([EAST0, POST, 0, NORTH0, 0, -POST])
srs = osr.SpatialReference()
srs.ImportFromEPSG(32610)
ds.SetProjection(srs.ExportToWkt())
ds.GetRasterBand(1).WriteArray(h)
ds = None

# Fixed objects in the local frame (metres from the SW corner of the resampled terrain): a grove
# of trees on a 25 m lattice, a line of telephone poles, two buildings and a watertower.
rows = ["id,kind,x_m,y_m,heading_deg"]
for i in range(8):
    for j in range(6):
        rows.append("tree%02d%d,tree,%.1f,%.1f,0" % (i, j, 2500 + 25 * i, 5000 + 25 * j))
for i in range(10):
    rows.append("pole%02d,telephone_pole,%.1f,4000.0,90" % (i, 1000 + 60 * i))
rows += ["house1,building,3000.0,3000.0,0", "house2,building,3040.0,3000.0,0", "tower1,watertower,4000.0,4500.0,0"]
with open("scenarios/fhl/fhl-objects.csv", "w") as f:
    f.write("\n".join(rows) + "\n")
