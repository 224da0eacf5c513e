# SPDX-License-Identifier: Apache-2.0
"""`pip install .` (pyproject.toml, the in-tree PEP 517 backend
tools/files/python/packaging/glider_build_backend.py) into a fresh venv made with
Debian's python3 --system-site-packages, offline (--no-index,
--no-build-isolation), then `import glider` from outside the source and build
trees. CTest python.pip_install (TIMEOUT 300: it configures CMake and builds
the one target glider_python in GLIDER_PIP_BUILD_DIR, from ccache)."""
import os
import subprocess
import sys
import tarfile
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
COMET_2016 = ROOT / "tests" / "data" / "real" / "dbd" / "comet-2016"


@pytest.fixture(scope="module")
def work(tmp_path_factory):
    if "GLIDER_PIP_BUILD_DIR" not in os.environ:
        pytest.skip("GLIDER_PIP_BUILD_DIR not set (run through CTest)")
    return tmp_path_factory.mktemp("pip")  # outside the source and build trees


def run(args, cwd, env=None):
    return subprocess.run([str(a) for a in args], cwd=cwd, env=env, check=True, capture_output=True, text=True)


def clean_env():
    # No PYTHONPATH into the build tree: the module must come from the venv.
    return {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME")}


def test_pip_install_into_a_venv_and_import_from_outside_the_tree(work):
    venv = work / "venv"
    run(["/usr/bin/python3", "-m", "venv", "--system-site-packages", venv], cwd=work)
    python = venv / "bin" / "python"
    wheels = work / "wheels"
    # The wheel first (to look into it), then the install from the source tree as users type it.
    run([python, "-m", "pip", "wheel", "--no-build-isolation", "--no-index", "--no-deps", "-w", wheels, ROOT],
        cwd=work, env=clean_env())
    (wheel,) = wheels.glob("glider-*.whl")
    names = zipfile.ZipFile(wheel).namelist()
    assert any(n.startswith("glider.cpython-") and n.endswith(".so") for n in names), names
    assert "glider-0.1.0.dist-info/RECORD" in names and "glider-0.1.0.dist-info/METADATA" in names
    run([python, "-m", "pip", "install", "--no-build-isolation", "--no-index", ROOT], cwd=work, env=clean_env())

    code = (
        "import glider, os\n"
        "print(glider.__file__)\n"
        f"log = glider.read_log({str(COMET_2016)!r})\n"
        "print(len(log), len(log.columns))\n"
        "print(os.environ.get('GLIDER_BOARDS_DIR'))\n"
        "print(glider.load_vehicle().name)\n"
    )
    env = {k: v for k, v in clean_env().items() if k != "GLIDER_BOARDS_DIR"}
    out = run([python, "-c", code], cwd=work, env=env).stdout.split("\n")
    module = Path(out[0])
    assert module.is_relative_to(venv), module  # the venv's copy, not the build tree's
    assert not module.is_relative_to(ROOT)
    assert out[1] == "3043 1465"
    # The boards/ the wheel installed, not the source tree's: the default vehicle from there.
    assert out[2] == str(venv / "share" / "glider" / "boards"), out[2]
    assert (venv / "share" / "glider" / "boards" / "gliders.toml").is_file()
    assert out[3] == "slocum_we01"

    listed = run([python, "-m", "pip", "show", "-f", "glider"], cwd=work, env=clean_env()).stdout
    assert "Version: 0.1.0" in listed and "Requires: numpy" in listed
    run([python, "-m", "pip", "uninstall", "-y", "glider"], cwd=work, env=clean_env())
    gone = subprocess.run([str(python), "-c", "import glider"], cwd=work, env=clean_env(), capture_output=True)
    assert gone.returncode != 0


def test_the_wheel_metadata_comes_from_the_project_files(tmp_path):
    """Version from CMakeLists.txt, dependencies from pyproject.toml, tag of this interpreter; the sdist."""
    sys.path.insert(0, str(ROOT / "tools" / "files" / "python" / "packaging"))
    try:
        import glider_build_backend as backend
    finally:
        sys.path.pop(0)
    assert backend._project()["version"] == "0.1.0"  # from CMakeLists.txt's project()
    tag = backend._tag()
    assert tag.startswith(f"cp{sys.version_info.major}{sys.version_info.minor}-") and "linux" in tag
    metadata = backend._metadata(backend._project())
    assert "Requires-Dist: numpy" in metadata and 'Requires-Dist: xarray; extra == "xarray"' in metadata
    # The sdist: the files git tracks (what pip needs to build the wheel from it), not the build trees.
    name = backend.build_sdist(str(tmp_path))
    with tarfile.open(tmp_path / name) as sdist:
        names = set(sdist.getnames())
    for needed in ("pyproject.toml", "CMakeLists.txt", "tools/files/python/packaging/glider_build_backend.py",
                   "tools/files/python/glider_module.cpp", "docs/python.md", "LICENSE", "PKG-INFO"):
        assert f"glider-0.1.0/{needed}" in names, needed
    assert not any(n.startswith("glider-0.1.0/build/") for n in names)
