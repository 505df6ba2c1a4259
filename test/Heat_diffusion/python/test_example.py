# The Python example of the manual runs and draws its picture.
import os
import subprocess
import sys

EXAMPLE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "examples", "Heat_diffusion",
                       "python", "diffuse_example.py")


def test_diffuse_example(mesh, tmp_path):
    _, _, path = mesh("fandisk.off")
    output = tmp_path / "fandisk_diffused.png"
    result = subprocess.run([sys.executable, EXAMPLE, path, str(output)], capture_output=True, text=True,
                            timeout=300, env=dict(os.environ, MPLCONFIGDIR=str(tmp_path)))
    assert result.returncode == 0, result.stderr
    heat = [float(line.split("total heat")[1]) for line in result.stdout.splitlines() if "total heat" in line]
    assert len(heat) == 3 and max(heat) - min(heat) <= 1e-12 * abs(heat[0])
    with open(output, "rb") as f:
        assert f.read(8) == b"\x89PNG\r\n\x1a\n"
    assert output.stat().st_size > 10000
