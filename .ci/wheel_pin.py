# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""wheel_pin.py WHEEL REQUIREMENT: in WHEEL's METADATA, the Requires-Dist of REQUIREMENT's project
becomes REQUIREMENT (vtk>=9.4 -> vtk==9.7.0: a wheel runs on the VTK it was built against only);
RECORD follows. The wheel is rewritten in place."""
import base64
import hashlib
import os
import re
import sys
import zipfile


def main(path, requirement):
    project = re.match(r"[A-Za-z0-9_.-]+", requirement).group(0)
    with zipfile.ZipFile(path) as old:
        entries = [(info, old.read(info.filename)) for info in old.infolist()]
    metadata = next(i.filename for i, _ in entries if i.filename.endswith(".dist-info/METADATA"))
    record = metadata[: -len("METADATA")] + "RECORD"
    pattern = re.compile(r"^Requires-Dist: %s\b[^\n]*$" % re.escape(project), re.M | re.I)
    contents = dict((i.filename, data) for i, data in entries)
    text, count = pattern.subn("Requires-Dist: " + requirement, contents[metadata].decode())
    if count != 1:
        sys.exit("wheel_pin.py: %s has %d Requires-Dist of %s, not one" % (path, count, project))
    contents[metadata] = text.encode()
    digest = base64.urlsafe_b64encode(hashlib.sha256(contents[metadata]).digest()).rstrip(b"=")
    lines = [
        "%s,sha256=%s,%d" % (metadata, digest.decode(), len(contents[metadata]))
        if line.startswith(metadata + ",") else line
        for line in contents[record].decode().splitlines()
    ]
    contents[record] = ("\n".join(lines) + "\n").encode()
    temporary = path + ".pinning"
    with zipfile.ZipFile(temporary, "w", zipfile.ZIP_DEFLATED) as new:
        for info, _ in entries:
            new.writestr(info, contents[info.filename], compress_type=zipfile.ZIP_DEFLATED)
    os.replace(temporary, path)
    print("wheel_pin.py: %s requires %s" % (os.path.basename(path), requirement))


if __name__ == "__main__":
    main(*sys.argv[1:])
