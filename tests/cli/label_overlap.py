"""Overlap of a study's labels (gzip or raw NRRD, uint8), as the realdata tests report it. Usage:
label_overlap.py STUDY.vsim LABEL_ID REFERENCE_ID [REFERENCE_ID ...] -> JSON on stdout: the label's voxel count and,
for each reference, its voxel count, Dice, recall (the share of the reference's voxels in the label) and the share
of the label's voxels inside the reference."""
import gzip
import json
import os
import sys


def voxels(bundle, artifact):
    path = os.path.join(bundle, "labels", artifact + ".nrrd")
    data = open(path, "rb").read()
    end = data.index(b"\n\n") + 2
    header, body = data[:end], data[end:]
    if b"encoding: gzip" in header:
        body = gzip.decompress(body)
    return body


def main():
    bundle, label_id, references = sys.argv[1], sys.argv[2], sys.argv[3:]
    label = voxels(bundle, label_id)
    in_label = {i for i, v in enumerate(label) if v}
    result = {"label": label_id, "label_voxels": len(in_label), "references": {}}
    for reference in references:
        ref = voxels(bundle, reference)
        if len(ref) != len(label):
            sys.exit(f"{reference} is on another grid than {label_id}")
        in_ref = {i for i, v in enumerate(ref) if v}
        both = len(in_label & in_ref)
        result["references"][reference] = {
            "voxels": len(in_ref),
            "dice": 2.0 * both / max(1, len(in_label) + len(in_ref)),
            "recall": both / max(1, len(in_ref)),
            "share_of_label": both / max(1, len(in_label)),
        }
    print(json.dumps(result, indent=1))


if __name__ == "__main__":
    main()
