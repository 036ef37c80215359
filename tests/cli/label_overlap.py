"""Overlap of a study's labels (gzip or raw NRRD, uint8), as the realdata tests report it. Usage:
label_overlap.py STUDY.vsim LABEL_ID REFERENCE_ID [REFERENCE_ID ...] [--except EXCEPT_ID] -> JSON on stdout: the
label's voxel count and, for each reference, its voxel count, Dice, recall (the share of the reference's voxels in the
label), the share of the label's voxels inside the reference and, with --except, the share inside the reference but
outside EXCEPT_ID (e.g. the heart mask outside the pulmonary-artery mask)."""
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
    arguments = sys.argv[1:]
    excepted = set()
    if "--except" in arguments:
        at = arguments.index("--except")
        excepted = {i for i, v in enumerate(voxels(arguments[0], arguments[at + 1])) if v}
        del arguments[at:at + 2]
    bundle, label_id, references = arguments[0], arguments[1], arguments[2:]
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
        if excepted:
            result["references"][reference]["share_of_label_outside_except"] = (
                len((in_label & in_ref) - excepted) / max(1, len(in_label)))
    print(json.dumps(result, indent=1))


if __name__ == "__main__":
    main()
