#!/usr/bin/python3
"""Carry a large case's fields for pictures from a machine without ParaView.

A million-particle run on a GPU machine writes ~70 MB a time directory; a
picture needs only positions and the coloured field, in single precision.

    fieldsForPictures.py pack CASE OUT.npz TIME BODY:FIELD[,FIELD] ...
        stores, in single precision, the position and the named fields of
        each BODY at TIME (the written time nearest it), with the id, its
        bodyProperties and the time's uniform/time
    fieldsForPictures.py unpack IN.npz CASE
        writes them back (double precision) into CASE/<time>/<body>/, a
        case that holds the same bodies at time 0 (generateParticles), and
        copies the bodies that are not there yet (fixed walls) from 0/; a
        time packed in several files (one per group of bodies) is unpacked
        file by file, in any order: packed fields overwrite copied ones

then, in CASE: particlesToVTK -fields '(U vonMises)' and renderParticles.
The fields are the solver's binary ones: a FoamFile header, then
'value nonuniform List<T> N(' with N raw values and ')' (arch in the
header: little-endian, 32-bit labels, 64-bit scalars).
(Debian: python3-numpy.)
"""
import os
import re
import shutil
import sys

import numpy as np

# Per kind of list: values per particle, binary type, FoamFile class.
KINDS = {"scalar": (1, np.float64, "scalarField"),
         "vector": (3, np.float64, "vectorField"),
         "label": (1, np.int32, "labelField")}


def readField(path):
    data = open(path, "rb").read()
    m = re.search(rb"value\s+nonuniform List<(\w+)> (\d+)\(", data)
    if not m:
        sys.exit(f"{path}: not a binary field of the solver")
    kind, n = m.group(1).decode(), int(m.group(2))
    width, dtype, _ = KINDS[kind]
    values = np.frombuffer(data, dtype=dtype, count=n*width, offset=m.end())
    return kind, values.reshape(n, width) if width > 1 else values


def writeField(path, kind, values, timeName, body, name):
    _, dtype, cls = KINDS[kind]
    header = f"""/*--------------------------------*- C++ -*----------------------------------*\\
  sphvcpm: fields carried for pictures (docs/validation/scripts/fieldsForPictures.py)
\\*---------------------------------------------------------------------------*/
FoamFile
{{
    version     2.0;
    format      binary;
    class       {cls};
    arch        "LSB;label=32;scalar=64";
    location    "{timeName}/{body}";
    object      {name};
}}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

"""
    n = len(values)
    with open(path, "wb") as f:
        f.write(header.encode())
        f.write(f"value           nonuniform List<{kind}> {n}(".encode())
        f.write(np.ascontiguousarray(values, dtype=dtype).tobytes())
        f.write(b")\n;\n")


def nearestTime(case, t):
    times = [d for d in os.listdir(case)
             if re.fullmatch(r"[0-9.eE+-]+", d) and os.path.isdir(os.path.join(case, d))]
    if not times:
        sys.exit(f"{case}: no time directories")
    return min(times, key=lambda d: abs(float(d) - t))


def pack(case, out, t, specs):
    timeName = nearestTime(case, float(t))
    arrays = {"time": np.array(timeName),
              "uniformTime": np.array(
                  open(os.path.join(case, timeName, "uniform", "time")).read())}
    for spec in specs:
        body, _, fields = spec.partition(":")
        d = os.path.join(case, timeName, body)
        for name in ["position", "id"] + [f for f in fields.split(",") if f]:
            kind, values = readField(os.path.join(d, name))
            arrays[f"{body}/{name}/{kind}"] = (
                values if kind == "label" else values.astype(np.float32))
        arrays[f"{body}/bodyProperties"] = np.array(
            open(os.path.join(d, "bodyProperties")).read())
    np.savez_compressed(out, **arrays)
    print(f"{out}: time {timeName}, {', '.join(specs)}")


def unpack(npz, case):
    a = np.load(npz)
    timeName = str(a["time"])
    bodies = set()
    os.makedirs(os.path.join(case, timeName, "uniform"), exist_ok=True)
    with open(os.path.join(case, timeName, "uniform", "time"), "w") as f:
        f.write(str(a["uniformTime"]))
    for key in a.files:
        parts = key.split("/")
        if len(parts) == 2:
            body = parts[0]
            os.makedirs(os.path.join(case, timeName, body), exist_ok=True)
            with open(os.path.join(case, timeName, body, "bodyProperties"), "w") as f:
                f.write(str(a[key]))
            bodies.add(body)
        elif len(parts) == 3:
            body, name, kind = parts
            os.makedirs(os.path.join(case, timeName, body), exist_ok=True)
            writeField(os.path.join(case, timeName, body, name), kind, a[key],
                       timeName, body, name)
    # A time may come in several files: a body that an earlier file brought
    # is not copied over from 0/.
    for body in os.listdir(os.path.join(case, "0")):
        src = os.path.join(case, "0", body)
        dst = os.path.join(case, timeName, body)
        if body != "uniform" and os.path.isdir(src) and not os.path.isdir(dst):
            shutil.copytree(src, dst)
    print(f"{case}/{timeName}: {', '.join(sorted(bodies))} unpacked")


if __name__ == "__main__":
    if len(sys.argv) >= 5 and sys.argv[1] == "pack":
        pack(sys.argv[2], sys.argv[3], sys.argv[4], sys.argv[5:])
    elif len(sys.argv) == 4 and sys.argv[1] == "unpack":
        unpack(sys.argv[2], sys.argv[3])
    else:
        sys.exit(__doc__)
