"""A minimal PEP 517 build backend using only the standard library.

The package is pure Python (the C library is installed separately), so a wheel is just a zip of
the ``bezsurf`` directory plus its metadata. Building needs no setuptools, wheel or network, which
keeps ``pip install ./bindings/python`` working on machines without a package index.
"""

import base64
import hashlib
import io
import os
import re
import tarfile
import zipfile

NAME = "bezsurf"
TAG = "py3-none-any"
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def _version():
    """The package's __version__, the one place the version is written."""
    with open(os.path.join(ROOT, NAME, "__init__.py"), encoding="utf-8") as f:
        return re.search(r'^__version__ = "([^"]+)"', f.read(), re.M).group(1)


VERSION = _version()
DIST_INFO = f"{NAME}-{VERSION}.dist-info"

METADATA = f"""Metadata-Version: 2.1
Name: {NAME}
Version: {VERSION}
Summary: Python binding (ctypes) of libbezsurf, rectangular tensor-product Bezier surface patches
Requires-Python: >=3.8
Provides-Extra: numpy
Requires-Dist: numpy; extra == "numpy"
"""

WHEEL = f"""Wheel-Version: 1.0
Generator: bezsurf_build
Root-Is-Purelib: true
Tag: {TAG}
"""


def _package_files():
    base = os.path.join(ROOT, NAME)
    for name in sorted(os.listdir(base)):
        if name.endswith(".py") or name == "py.typed":
            yield f"{NAME}/{name}", os.path.join(base, name)


def _record_line(arcname, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return f"{arcname},sha256={digest},{len(data)}\n"


def _write_wheel(directory, files):
    filename = f"{NAME}-{VERSION}-{TAG}.whl"
    record = ""
    with zipfile.ZipFile(os.path.join(directory, filename), "w", zipfile.ZIP_DEFLATED) as z:
        for arcname, data in files:
            z.writestr(arcname, data)
            record += _record_line(arcname, data)
        record += f"{DIST_INFO}/RECORD,,\n"
        z.writestr(f"{DIST_INFO}/RECORD", record)
    return filename


def _metadata_files():
    return [(f"{DIST_INFO}/METADATA", METADATA.encode()), (f"{DIST_INFO}/WHEEL", WHEEL.encode())]


def get_requires_for_build_wheel(config_settings=None):
    return []


def get_requires_for_build_sdist(config_settings=None):
    return []


get_requires_for_build_editable = get_requires_for_build_wheel


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    os.makedirs(os.path.join(metadata_directory, DIST_INFO), exist_ok=True)
    for arcname, data in _metadata_files():
        with open(os.path.join(metadata_directory, arcname), "wb") as f:
            f.write(data)
    return DIST_INFO


prepare_metadata_for_build_editable = prepare_metadata_for_build_wheel


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    files = []
    for arcname, path in _package_files():
        with open(path, "rb") as f:
            files.append((arcname, f.read()))
    return _write_wheel(wheel_directory, files + _metadata_files())


def build_editable(wheel_directory, config_settings=None, metadata_directory=None):
    # A .pth file puts the source directory on sys.path.
    pth = (ROOT + "\n").encode()
    return _write_wheel(wheel_directory, [(f"{NAME}.pth", pth)] + _metadata_files())


def build_sdist(sdist_directory, config_settings=None):
    filename = f"{NAME}-{VERSION}.tar.gz"
    top = f"{NAME}-{VERSION}"
    with tarfile.open(os.path.join(sdist_directory, filename), "w:gz") as tar:
        for rel in ["pyproject.toml", "README.md", "_build/bezsurf_build.py"]:
            tar.add(os.path.join(ROOT, rel), f"{top}/{rel}")
        for arcname, path in _package_files():
            tar.add(path, f"{top}/{arcname}")
        info = tarfile.TarInfo(f"{top}/PKG-INFO")
        data = METADATA.encode()
        info.size = len(data)
        tar.addfile(info, io.BytesIO(data))
    return filename
