"""A small PEP 517 build backend using only the standard library.

A wheel is the ``bezsurf`` package, its metadata (read from ``pyproject.toml``) and, when the
package is built from the libbezsurf source tree, the C library ``libbezsurf.so.1`` compiled from
that tree with CMake (``cmake`` and a C compiler are the only tools needed). Building needs no
setuptools, wheel or network, so ``pip install ./bindings/python`` works on machines without a
package index, with or without build isolation.

Config setting ``bundle`` (``pip install --config-settings bundle=...``), also read from the
environment variable ``BEZSURF_BUNDLE``:

* ``auto`` (default): bundle the library when the C sources and ``cmake`` are there, else build
  a pure-Python wheel that uses an installed library;
* ``yes``: bundle the library, fail if it cannot be built;
* ``no``: pure-Python wheel (for packagers shipping the C library separately).
"""

import base64
import hashlib
import io
import os
import re
import shutil
import subprocess
import sys
import sysconfig
import tarfile
import tempfile
import zipfile

NAME = "bezsurf"
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SOURCE_TREE = os.path.dirname(os.path.dirname(ROOT))   # bindings/python -> the C sources

if sys.platform == "darwin":
    SONAME = "libbezsurf.1.dylib"
elif sys.platform == "win32":
    SONAME = "bezsurf.dll"
else:
    SONAME = "libbezsurf.so.1"


# ---- pyproject.toml ---------------------------------------------------------------------------

def _parse_value(text):
    """One TOML value of the subset pyproject.toml uses: strings, arrays, inline tables, bools."""
    text = text.strip()
    value, rest = _value(text, 0)
    if text[rest:].strip():
        raise ValueError(f"unexpected text after a value: {text[rest:]!r}")
    return value


def _skip(text, i):
    while i < len(text):
        if text[i] in " \t\r\n,":
            i += 1
        elif text[i] == "#":
            while i < len(text) and text[i] != "\n":
                i += 1
        else:
            break
    return i


def _value(text, i):
    c = text[i]
    if c in "\"'":
        end = text.index(c, i + 1)
        s = text[i + 1:end]
        if c == '"':
            s = s.encode("latin-1", "backslashreplace").decode("unicode_escape")
        return s, end + 1
    if c == "[":
        items, i = [], _skip(text, i + 1)
        while text[i] != "]":
            item, i = _value(text, i)
            items.append(item)
            i = _skip(text, i)
        return items, i + 1
    if c == "{":
        table, i = {}, _skip(text, i + 1)
        while text[i] != "}":
            m = re.compile(r'\s*("[^"]*"|[A-Za-z0-9_.-]+)\s*=\s*').match(text, i)
            if not m:
                raise ValueError(f"bad inline table at {text[i:i + 20]!r}")
            item, i = _value(text, m.end())
            table[m.group(1).strip('"')] = item
            i = _skip(text, i)
        return table, i + 1
    m = re.compile(r"true|false|[+-]?[0-9][0-9_]*").match(text, i)
    if not m:
        raise ValueError(f"unsupported TOML value at {text[i:i + 20]!r}")
    word = m.group(0)
    return (word == "true") if word in ("true", "false") else int(word.replace("_", "")), m.end()


def parse_toml(text):
    """Parse the TOML subset of our pyproject.toml (tomllib is used instead where it exists)."""
    data = {}
    table = data
    lines = text.splitlines()
    n = 0
    while n < len(lines):
        line = lines[n].strip()
        n += 1
        if not line or line.startswith("#"):
            continue
        if line.startswith("["):
            table = data
            for part in line.strip("[]").split("."):
                table = table.setdefault(part.strip().strip('"'), {})
            continue
        key, _, value = line.partition("=")
        # multi-line arrays and inline tables: read on until the brackets balance
        while value.count("[") + value.count("{") > value.count("]") + value.count("}"):
            value += "\n" + lines[n]
            n += 1
        value = re.sub(r"(?m)#[^\"'\n]*$", "", value)
        table[key.strip().strip('"')] = _parse_value(value)
    return data


def _pyproject():
    with open(os.path.join(ROOT, "pyproject.toml"), "rb") as f:
        raw = f.read()
    try:
        import tomllib
    except ImportError:  # Python < 3.11
        return parse_toml(raw.decode("utf-8"))
    return tomllib.loads(raw.decode("utf-8"))


def _version():
    """The package's __version__, the one place the version is written."""
    with open(os.path.join(ROOT, NAME, "__init__.py"), encoding="utf-8") as f:
        return re.search(r'^__version__ = "([^"]+)"', f.read(), re.M).group(1)


def metadata_text(project=None):
    """Core metadata (METADATA / PKG-INFO) from the [project] table of pyproject.toml."""
    project = project if project is not None else _pyproject()["project"]
    lines = ["Metadata-Version: 2.1", f"Name: {project['name']}", f"Version: {_version()}"]
    if "description" in project:
        lines.append(f"Summary: {project['description']}")
    if "keywords" in project:
        lines.append(f"Keywords: {','.join(project['keywords'])}")
    for person in project.get("authors", []):
        if "email" in person:
            lines.append(f"Author-email: {person.get('name', '')} <{person['email']}>".replace(
                ":  <", ": <"))
        elif "name" in person:
            lines.append(f"Author: {person['name']}")
    lic = project.get("license")
    if isinstance(lic, dict) and "text" in lic:
        lines.append(f"License: {lic['text']}")
    elif isinstance(lic, str):
        lines.append(f"License: {lic}")
    for label, url in project.get("urls", {}).items():
        lines.append(f"Project-URL: {label}, {url}")
    for classifier in project.get("classifiers", []):
        lines.append(f"Classifier: {classifier}")
    if "requires-python" in project:
        lines.append(f"Requires-Python: {project['requires-python']}")
    for dep in project.get("dependencies", []):
        lines.append(f"Requires-Dist: {dep}")
    for extra, deps in project.get("optional-dependencies", {}).items():
        lines.append(f"Provides-Extra: {extra}")
        for dep in deps:
            marker = f'extra == "{extra}"'
            lines.append(f"Requires-Dist: {dep}; {marker}" if ";" not in dep
                         else f"Requires-Dist: {dep} and {marker}")
    body = ""
    readme = project.get("readme")
    if isinstance(readme, str):
        readme = {"file": readme}
    if isinstance(readme, dict):
        if "file" in readme:
            with open(os.path.join(ROOT, readme["file"]), encoding="utf-8") as f:
                body = f.read()
            kind = "text/markdown" if readme["file"].endswith(".md") else "text/plain"
        else:
            body = readme.get("text", "")
            kind = "text/plain"
        lines.append(f"Description-Content-Type: {readme.get('content-type', kind)}")
    return "\n".join(lines) + "\n\n" + body


# ---- the C library ------------------------------------------------------------------------------

def _bundle_mode(config_settings):
    mode = (config_settings or {}).get("bundle") or os.environ.get("BEZSURF_BUNDLE") or "auto"
    if mode not in ("auto", "yes", "no"):
        raise ValueError(f"bundle must be auto, yes or no, not {mode!r}")
    return mode


def _log(message):
    print(f"bezsurf_build: {message}", file=sys.stderr, flush=True)


def build_library(mode):
    """The bytes of libbezsurf built from the source tree, or None (pure-Python wheel)."""
    if mode == "no":
        return None
    why = None
    cmake = shutil.which("cmake")
    if not os.path.exists(os.path.join(SOURCE_TREE, "include", "bezsurf.h")):
        why = f"no libbezsurf sources in {SOURCE_TREE}"
    elif cmake is None:
        why = "cmake is not installed"
    if why is None:
        with tempfile.TemporaryDirectory(prefix="bezsurf-build-") as build:
            configure = [cmake, "-S", SOURCE_TREE, "-B", build, "-DCMAKE_BUILD_TYPE=Release",
                         "-DBUILD_SHARED_LIBS=ON", "-DBUILD_TESTING=OFF",
                         "-DBS_BUILD_EXAMPLES=OFF", "-DBS_BUILD_TOOLS=OFF", "-DBS_BUILD_BENCH=OFF"]
            compile_ = [cmake, "--build", build, "--target", "bezsurf", "--parallel",
                        str(min(os.cpu_count() or 1, 4))]
            for cmd in (configure, compile_):
                r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
                if r.returncode != 0:
                    why = f"{' '.join(cmd[:2])} failed:\n{r.stdout.decode(errors='replace')}"
                    break
            else:
                for dirpath, _, files in os.walk(build):
                    if SONAME in files:
                        with open(os.path.realpath(os.path.join(dirpath, SONAME)), "rb") as f:
                            _log(f"bundling {SONAME} built from {SOURCE_TREE}")
                            return f.read()
                why = f"the build made no {SONAME}"
    if mode == "yes":
        raise RuntimeError(f"cannot bundle libbezsurf: {why}")
    _log(f"building a pure-Python wheel ({why}); libbezsurf must be installed separately")
    return None


# ---- wheels and sdists ----------------------------------------------------------------------

def _dist_info():
    return f"{NAME}-{_version()}.dist-info"


def _package_files():
    base = os.path.join(ROOT, NAME)
    for name in sorted(os.listdir(base)):
        if name.endswith((".py", ".pyi")) or name == "py.typed":
            yield f"{NAME}/{name}", os.path.join(base, name)


def _license_file():
    for path in (os.path.join(ROOT, "LICENSE"), os.path.join(SOURCE_TREE, "LICENSE")):
        if os.path.exists(path):
            return path
    return None


def _record_line(arcname, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return f"{arcname},sha256={digest},{len(data)}\n"


def _platform_tag():
    return re.sub(r"[^A-Za-z0-9]", "_", sysconfig.get_platform())


def _write_wheel(directory, files, tag):
    filename = f"{NAME}-{_version()}-{tag}.whl"
    dist_info = _dist_info()
    record = ""
    with zipfile.ZipFile(os.path.join(directory, filename), "w", zipfile.ZIP_DEFLATED) as z:
        for arcname, data, mode in files:
            info = zipfile.ZipInfo(arcname, date_time=(2020, 1, 1, 0, 0, 0))
            info.external_attr = (0o100000 | mode) << 16
            info.compress_type = zipfile.ZIP_DEFLATED
            z.writestr(info, data)
            record += _record_line(arcname, data)
        record += f"{dist_info}/RECORD,,\n"
        z.writestr(f"{dist_info}/RECORD", record)
    return filename


def _metadata_files(pure):
    dist_info = _dist_info()
    tag = "py3-none-any" if pure else f"py3-none-{_platform_tag()}"
    wheel = (f"Wheel-Version: 1.0\nGenerator: bezsurf_build\n"
             f"Root-Is-Purelib: {'true' if pure else 'false'}\nTag: {tag}\n")
    files = [(f"{dist_info}/METADATA", metadata_text().encode(), 0o644),
             (f"{dist_info}/WHEEL", wheel.encode(), 0o644)]
    lic = _license_file()
    if lic:
        with open(lic, "rb") as f:
            files.append((f"{dist_info}/LICENSE", f.read(), 0o644))
    return files, tag


def get_requires_for_build_wheel(config_settings=None):
    return []


def get_requires_for_build_sdist(config_settings=None):
    return []


get_requires_for_build_editable = get_requires_for_build_wheel


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    dist_info = _dist_info()
    os.makedirs(os.path.join(metadata_directory, dist_info), exist_ok=True)
    files, _ = _metadata_files(True)
    for arcname, data, _mode in files:
        with open(os.path.join(metadata_directory, arcname), "wb") as f:
            f.write(data)
    return dist_info


prepare_metadata_for_build_editable = prepare_metadata_for_build_wheel


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    files = []
    for arcname, path in _package_files():
        with open(path, "rb") as f:
            files.append((arcname, f.read(), 0o644))
    library = build_library(_bundle_mode(config_settings))
    if library is not None:
        files.append((f"{NAME}/{SONAME}", library, 0o755))
    meta, tag = _metadata_files(library is None)
    return _write_wheel(wheel_directory, files + meta, tag)


def build_editable(wheel_directory, config_settings=None, metadata_directory=None):
    # A .pth file puts the source directory on sys.path; the library is found as installed.
    meta, tag = _metadata_files(True)
    return _write_wheel(wheel_directory, [(f"{NAME}.pth", (ROOT + "\n").encode(), 0o644)] + meta,
                        tag)


def build_sdist(sdist_directory, config_settings=None):
    """The Python package alone: a wheel built from it uses an installed libbezsurf."""
    top = f"{NAME}-{_version()}"
    filename = f"{top}.tar.gz"
    with tarfile.open(os.path.join(sdist_directory, filename), "w:gz") as tar:
        for rel in ["pyproject.toml", "README.md", "_build/bezsurf_build.py"]:
            tar.add(os.path.join(ROOT, rel), f"{top}/{rel}")
        for arcname, path in _package_files():
            tar.add(path, f"{top}/{arcname}")
        lic = _license_file()
        if lic:
            tar.add(lic, f"{top}/LICENSE")
        info = tarfile.TarInfo(f"{top}/PKG-INFO")
        data = metadata_text().encode()
        info.size = len(data)
        tar.addfile(info, io.BytesIO(data))
    return filename
