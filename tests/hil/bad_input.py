# SPDX-License-Identifier: Apache-2.0
"""The hil checks' bad-input rule: each file built here must be refused with
a ValueError that names the file and says what (line, key, value)."""
import os


def check_refused(check, reader, directory, cases):
    """cases: (file name, text, what the message must say); reader(path) must raise ValueError."""
    for name, text, want in cases:
        path = os.path.join(directory, name)
        with open(path, "w") as f:
            f.write(text)
        try:
            reader(path)
            check(False, "%s refused" % name)
        except ValueError as e:
            check(path in str(e) and want in str(e), "%s refused: %s" % (name, e))
