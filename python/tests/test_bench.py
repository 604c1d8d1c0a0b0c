"""python/bench.py runs end to end (a smoke run; the figures are in docs/python.md)."""
import json
import os
import subprocess
import sys

from conftest import SOURCE_DIR


def test_bench_script_runs(ssl_images_dir, cli, tmp_path):
    images = sorted(str(p) for p in ssl_images_dir.glob("*.png"))[:3]
    out = tmp_path / "bench.json"
    subprocess.run([sys.executable, str(SOURCE_DIR / "python" / "bench.py"), "--cli", str(cli), "--repeat", "1",
                    "--rounds", "1", "--json", str(out), *images], check=True, env=os.environ, stdout=subprocess.DEVNULL)
    result = json.loads(out.read_text())
    assert result["images"] == 3 and result["sizes"] == ["640x480"]
    assert result["python_ms"] > 0 and result["cpp_in_process_ms"] > 0 and result["fieldlines_bench_ms"] > 0
