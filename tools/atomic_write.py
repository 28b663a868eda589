"""Writing a file atomically, for the project's Python scripts (bench/report.py, docs/audit_html.py).

The text or bytes go to a uniquely named temporary file in the target's own folder (created with
O_EXCL by tempfile.mkstemp, so never through a link), which is then renamed over the target: a reader
sees the old file or the new one, never half of one, and a link planted at the target is replaced,
its own target left alone. On any failure the temporary file is removed and the target is untouched.
"""

import os
import tempfile


def write_atomically(path, data):
    """Writes `data` (str, as UTF-8, or bytes) to `path` atomically; the file gets mode 0644."""
    folder = os.path.dirname(os.path.abspath(path))
    fd, temporary = tempfile.mkstemp(prefix="." + os.path.basename(path) + ".tmp-", dir=folder)
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data.encode("utf-8") if isinstance(data, str) else data)
        os.chmod(temporary, 0o644)  # mkstemp's 0600 would hide the file from other readers
        os.replace(temporary, path)
    except BaseException:
        os.unlink(temporary)
        raise


def copy_atomically(source, path):
    """Copies the file `source` to `path` atomically (as write_atomically)."""
    with open(source, "rb") as f:
        write_atomically(path, f.read())
