# SPDX-License-Identifier: Apache-2.0
"""PEP 517 build backend for `pip install .` (pyproject.toml): configures the
project with CMake, builds the one target glider_python, and packs the module
into a wheel. In-tree because Debian 12 packages no CMake-aware backend
(scikit-build-core, scikit-build); stdlib only, so it needs nothing from PyPI.

The build directory is build/pip in the source tree, or GLIDER_PIP_BUILD_DIR,
or --config-settings build-dir=DIR; ccache is used when installed (or as
CMAKE_CXX_COMPILER_LAUNCHER says), so unchanged sources compile from cache.
"""
import base64
import csv
import hashlib
import io
import os
import re
import shutil
import subprocess
import sys
import sysconfig
import tarfile
import tomllib
import zipfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[4]
TARGET = "glider_python"


def _project():
    with open(ROOT / "pyproject.toml", "rb") as f:
        project = tomllib.load(f)["project"]
    cmake = (ROOT / "CMakeLists.txt").read_text()
    match = re.search(r"project\(\s*glider\s+VERSION\s+([0-9.]+)", cmake)
    if not match:
        raise RuntimeError(f"{ROOT / 'CMakeLists.txt'}: no project(glider VERSION ...)")
    project["version"] = match.group(1)
    return project


def _dist_info_name(project):
    return f"{project['name']}-{project['version']}.dist-info"


def _metadata(project):
    lines = [
        "Metadata-Version: 2.1",
        f"Name: {project['name']}",
        f"Version: {project['version']}",
        f"Summary: {project['description']}",
        f"License: {project['license']['text']}",
        f"Requires-Python: {project['requires-python']}",
    ]
    lines += [f"Requires-Dist: {d}" for d in project.get("dependencies", [])]
    for extra, deps in project.get("optional-dependencies", {}).items():
        lines.append(f"Provides-Extra: {extra}")
        lines += [f'Requires-Dist: {d}; extra == "{extra}"' for d in deps]
    lines.append("Description-Content-Type: text/markdown")
    return "\n".join(lines) + "\n\n" + (ROOT / project["readme"]).read_text()


def _tag():
    # The module is built for this interpreter (CPython, its ABI, this platform).
    version = f"cp{sys.version_info.major}{sys.version_info.minor}"
    platform = re.sub(r"[-.]", "_", sysconfig.get_platform())
    return f"{version}-{version}-{platform}"


def _wheel_file(tag):
    return f"Wheel-Version: 1.0\nGenerator: glider_build_backend\nRoot-Is-Purelib: false\nTag: {tag}\n"


def _build_dir(config_settings):
    settings = config_settings or {}
    chosen = settings.get("build-dir") or os.environ.get("GLIDER_PIP_BUILD_DIR")
    return Path(chosen).resolve() if chosen else ROOT / "build" / "pip"


def _run(command):
    print("glider_build_backend:", " ".join(map(str, command)), file=sys.stderr, flush=True)
    subprocess.run(command, check=True, stdout=sys.stderr)


def _build_module(config_settings):
    build = _build_dir(config_settings)
    suffix = sysconfig.get_config_var("EXT_SUFFIX")
    if not (build / "CMakeCache.txt").exists():
        # The library and its module only: no test programs (nor CppUTest) needed.
        configure = ["cmake", "-S", ROOT, "-B", build, "-DCMAKE_BUILD_TYPE=Release", "-DBUILD_TESTING=OFF"]
        if shutil.which("ninja"):
            configure += ["-G", "Ninja"]
        if "CMAKE_CXX_COMPILER_LAUNCHER" not in os.environ and shutil.which("ccache"):
            configure += ["-DCMAKE_CXX_COMPILER_LAUNCHER=ccache", "-DCMAKE_C_COMPILER_LAUNCHER=ccache"]
        _run(configure)
    _run(["cmake", "--build", build, "--target", TARGET])
    modules = sorted((build / "tools" / "files" / "python").glob("glider.*.so"))
    if not modules:
        raise RuntimeError(f"{build}: the build made no glider module (pybind11-dev, python3-dev installed?)")
    module = modules[0]
    if not module.name.endswith(suffix):
        raise RuntimeError(
            f"{module} is built for Debian's /usr/bin/python3, not for this interpreter ({sys.executable}, "
            f"modules *{suffix}): install with /usr/bin/python3 or a venv made from it")
    return module


def _record_line(name, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return [name, f"sha256={digest}", str(len(data))]


def get_requires_for_build_wheel(config_settings=None):
    return []


def get_requires_for_build_sdist(config_settings=None):
    return []


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    project = _project()
    info = Path(metadata_directory) / _dist_info_name(project)
    info.mkdir(parents=True, exist_ok=True)
    (info / "METADATA").write_text(_metadata(project))
    (info / "WHEEL").write_text(_wheel_file(_tag()))
    return info.name


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    project = _project()
    module = _build_module(config_settings)
    tag = _tag()
    info = _dist_info_name(project)
    files = {
        module.name: module.read_bytes(),
        f"{info}/METADATA": _metadata(project).encode(),
        f"{info}/WHEEL": _wheel_file(tag).encode(),
        f"{info}/LICENSE": (ROOT / "LICENSE").read_bytes(),
    }
    # boards/ (vehicle files, gliders.toml) to <data>/share/glider/boards, where the installed module looks.
    data = f"{project['name']}-{project['version']}.data/data/share/glider/boards"
    for path in sorted((ROOT / "boards").rglob("*")):
        if path.is_file():
            files[f"{data}/{path.relative_to(ROOT / 'boards').as_posix()}"] = path.read_bytes()
    name = f"{project['name']}-{project['version']}-{tag}.whl"
    record = io.StringIO()
    writer = csv.writer(record, lineterminator="\n")
    with zipfile.ZipFile(Path(wheel_directory) / name, "w", zipfile.ZIP_DEFLATED) as wheel:
        for path, data in files.items():
            wheel.writestr(path, data)
            writer.writerow(_record_line(path, data))
        writer.writerow([f"{info}/RECORD", "", ""])
        wheel.writestr(f"{info}/RECORD", record.getvalue())
    return name


def build_sdist(sdist_directory, config_settings=None):
    """The files git tracks (the source tree as committed), as NAME-VERSION/..."""
    project = _project()
    base = f"{project['name']}-{project['version']}"
    listed = subprocess.run(["git", "-C", ROOT, "ls-files", "-z"], check=True, capture_output=True).stdout
    name = f"{base}.tar.gz"
    with tarfile.open(Path(sdist_directory) / name, "w:gz") as sdist:
        for path in filter(None, listed.decode().split("\0")):
            if (ROOT / path).is_file():
                sdist.add(ROOT / path, arcname=f"{base}/{path}")
        info = tarfile.TarInfo(f"{base}/PKG-INFO")
        data = _metadata(project).encode()
        info.size = len(data)
        sdist.addfile(info, io.BytesIO(data))
    return name
