"""Counts the nonzero voxels of a NIfTI-1 file (.nii or .nii.gz), independently of VascuSim's readers (the truth for
a mask's import). Usage: nifti_count.py FILE -> the count on stdout."""
import array
import gzip
import struct
import sys

TYPES = {2: "B", 4: "h", 8: "i", 16: "f", 64: "d", 256: "b", 512: "H", 768: "I"}


def main():
    path = sys.argv[1]
    data = (gzip.open if path.endswith(".gz") else open)(path, "rb").read()
    endian = "<" if struct.unpack("<i", data[0:4])[0] == 348 else ">"
    dims = struct.unpack(endian + "8h", data[40:56])
    datatype = struct.unpack(endian + "h", data[70:72])[0]
    offset = int(struct.unpack(endian + "f", data[108:112])[0])
    count = dims[1] * dims[2] * dims[3]
    values = array.array(TYPES[datatype])
    values.frombytes(data[offset:offset + count * values.itemsize])
    if (endian == "<") != (sys.byteorder == "little"):
        values.byteswap()
    print(sum(1 for v in values if v != 0))


if __name__ == "__main__":
    main()
