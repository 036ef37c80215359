"""Writes a copy of a raw int16 NRRD (a study's CT) as stored values without their rescale, as an export that
lost the DICOM Rescale Intercept would: value + 1024 (air 0, water 1024). Usage: stored_values_nrrd.py IN OUT"""
import array
import sys


def main():
    source, target = sys.argv[1], sys.argv[2]
    data = open(source, "rb").read()
    end = data.index(b"\n\n") + 2
    header = data[:end]
    if b"encoding: raw" not in header or b"endian: little" not in header or sys.byteorder != "little":
        sys.exit("the source NRRD must be raw little-endian int16")
    voxels = array.array("h", data[end:])
    stored = array.array("h", (min(max(v + 1024, 0), 32767) for v in voxels))
    with open(target, "wb") as out:
        out.write(header + stored.tobytes())


if __name__ == "__main__":
    main()
