"""`cmake --install` puts the module into the prefix's Python path, and it loads our libraries
installed beside it (RPATH), not the build tree's."""
import os
import subprocess
import sys

from conftest import require


def test_installed_module_imports_from_the_prefix(tmp_path):
    build = require("the build folder (FIELDLINES_BUILD_DIR)", os.environ.get("FIELDLINES_BUILD_DIR"))
    relative = os.environ.get("FIELDLINES_PYTHON_INSTALL_DIR")
    require("FIELDLINES_PYTHON_INSTALL_DIR", relative and build)
    prefix = tmp_path / "prefix"
    for component in ("detect", "libs", "python"):  # the .deb's python3-fieldlines and what it depends on
        subprocess.run(["cmake", "--install", str(build), "--prefix", str(prefix), "--component", component],
                       check=True, stdout=subprocess.DEVNULL)
    site = prefix / relative
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "LD_LIBRARY_PATH")}
    env["PYTHONPATH"] = str(site)
    probe = ("import fieldlines, numpy as np; "
             "print(fieldlines.__file__); "
             "print(len(fieldlines.LineDetector().detect(np.zeros((48, 64, 3), np.uint8))))")
    out = subprocess.run([sys.executable, "-c", probe], env=env, cwd=tmp_path, check=True, capture_output=True, text=True)
    module, count = out.stdout.split()
    assert module.startswith(str(site)) and count == "0"
    maps = subprocess.run(
        [sys.executable, "-c", "import fieldlines; print(open('/proc/self/maps').read())"],
        env=env, cwd=tmp_path, check=True, capture_output=True, text=True).stdout
    ours = {line.split()[-1] for line in maps.splitlines() if "libfieldlines_" in line}
    assert ours and all(path.startswith(str(prefix)) for path in ours), ours
