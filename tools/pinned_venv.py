"""Re-running a tool script under a virtual environment of its own, created on first use, so
its Python packages are the same versions on every machine and never touch the system's."""
import os
import subprocess
import sys
from pathlib import Path


def ensure_venv(venv, script, packages, what):
    """Re-executes `script` (with this process's arguments) under `venv`'s Python, first creating
    the environment and installing `packages` (pip install arguments: `["-r", file]` or pinned
    names) if it does not exist; returns at once when already running there. `what` names the
    packages in the one-line message printed on creation."""
    venv = Path(venv)
    python = venv / "bin" / "python"
    if Path(sys.prefix).resolve() == venv.resolve():
        return
    if not python.exists():
        print(f"creating {venv} ({what})", file=sys.stderr)
        subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)
        subprocess.run([str(python), "-m", "pip", "install", "--quiet", *packages], check=True)
    script = str(Path(script).resolve())
    os.execv(str(python), [str(python), script] + sys.argv[1:])
