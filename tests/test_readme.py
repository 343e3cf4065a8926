"""README.md cannot rot: every shell command and Python block it shows runs, in order, as written.

The blocks run in a temporary directory holding a copy of ``examples/`` (a clone's root as
far as the README is concerned), with the virtual environment's ``bin`` first on ``PATH``,
so ``asperity`` and ``python`` are the environment's, as after ``source
.venv/bin/activate``.  Skipped, with the reason: the set-up lines (``python3 -m venv``,
``pip install``, which need the network and build the environment these tests run in) and
``source .venv/bin/activate`` itself, and the lines of :data:`NOT_RUN` (a placeholder
for a cluster).  ``asperity explore`` serves until Ctrl-C: it runs with ``--no-browser
--port 0``, and is stopped with SIGINT once it has printed its address.  Python blocks run
with warnings turned into errors.
"""

import os
import re
import shutil
import signal
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
README = ROOT / "README.md"

#: Lines not run, by what they start with or contain: set-up (network) and activation.
SETUP = ("python3 -m venv", "pip install", ".venv/bin/pip", "source .venv/bin/activate")
#: Lines not run, with the reason.
NOT_RUN = {"--scheduler tcp://HOST": "a placeholder for one's own Dask cluster ('...' for the options)"}


def blocks() -> list[tuple[str, str]]:
    """(language, text) of every fenced block of README.md, in order."""
    return [(m.group(1), m.group(2)) for m in re.finditer(r"^```(\w+)\n(.*?)^```", README.read_text("utf-8"),
                                                             re.M | re.S)]


def steps() -> list[tuple[str, str]]:
    """What runs: ('bash', one command line) or ('python', one block), in README order."""
    out = []
    for lang, text in blocks():
        if lang == "bash":
            for line in re.sub(r"\\\n\s*", " ", text).splitlines():  # continuation lines joined
                command = line.strip()
                if command and not command.startswith("#") and not any(s in command for s in (*SETUP, *NOT_RUN)):
                    out.append(("bash", command))
        elif lang == "python":
            out.append(("python", text))
    return out


def test_the_two_set_up_commands_are_what_ci_runs():
    bash = [text.strip() for lang, text in blocks() if lang == "bash"]
    assert bash[0] == 'python3 -m venv .venv && .venv/bin/pip install -e ".[all]" && .venv/bin/asperity reproduce'
    assert bash[1] == '.venv/bin/pip install -e ".[test]" && .venv/bin/python -m pytest'
    ci = (ROOT / ".ci" / "run").read_text("utf-8")
    assert "python3 -m venv .venv" in ci and '.venv/bin/python -m pip install --quiet -e ".[all,test]"' in ci
    assert re.search(r"^\.venv/bin/python -m pytest\b", ci, re.M)


def test_readme_cites_the_paper_without_outside_links():
    text = README.read_text("utf-8")
    assert "Journal of Tribology" in text and "125" in text and "700-708 (2003)" in text
    assert "doi.org/10.1115/1.1572515" in text
    for target in re.findall(r"\]\(([^)]+)\)", text):
        if not target.startswith(("http://", "https://", "#")):
            assert (ROOT / target.split("#")[0]).exists(), f"README links to {target}, not in the repository"
            assert not target.startswith(("/", "..")), f"README links outside the repository: {target}"


def test_readme_shows_commands_and_python():
    kinds = [k for k, _ in steps()]
    assert kinds.count("bash") >= 10 and kinds.count("python") >= 2
    # The scan exists before it is used.
    texts = [s for _, s in steps()]
    first_use = next(i for i, t in enumerate(texts) if "afm-gold/gold_scan.x3p" in t)
    assert any("examples/afm_gold.py" in t for t in texts[:first_use])


@pytest.fixture(scope="module")
def workdir(tmp_path_factory):
    pytest.importorskip("matplotlib")
    pytest.importorskip("SurfaceTopography")
    pytest.importorskip("pint")
    pytest.importorskip("pandas")
    path = tmp_path_factory.mktemp("readme")
    shutil.copytree(ROOT / "examples", path / "examples")
    return path


def _explore(text: str, workdir, env) -> subprocess.CompletedProcess:
    """Run the README's ``asperity explore`` line without a browser on a free port; stop it with SIGINT."""
    pytest.importorskip("bokeh")
    argv = text.split("#", 1)[0].split() + ["--no-browser", "--port", "0"]
    proc = subprocess.Popen(argv, cwd=workdir, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        first = proc.stdout.readline()  # 'asperity explore: serving http://127.0.0.1:PORT/ (Ctrl-C to stop)'
        assert "serving http://127.0.0.1:" in first, first
        proc.send_signal(signal.SIGINT)
        out, err = proc.communicate(timeout=60)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.communicate()
    return subprocess.CompletedProcess(argv, proc.returncode, first + out, err)


def test_every_readme_step_runs(workdir):
    env = {**os.environ, "PATH": f"{Path(sys.executable).parent}{os.pathsep}{os.environ.get('PATH', '')}",
           "MPLBACKEND": "Agg"}
    env.pop("PYTHONPATH", None)
    for kind, text in steps():
        if kind == "bash" and text.startswith("asperity explore"):
            proc = _explore(text, workdir, env)
        elif kind == "bash":
            proc = subprocess.run(text, shell=True, cwd=workdir, env=env, capture_output=True, text=True, timeout=600)
        else:
            proc = subprocess.run([sys.executable, "-W", "error", "-c", text], cwd=workdir, env=env,
                                  capture_output=True, text=True, timeout=600)
        shown = text if kind == "bash" else text.splitlines()[0] + " ..."
        assert proc.returncode == 0, f"README {kind} step failed: {shown}\n{proc.stderr[-2000:]}"
        assert "Traceback" not in proc.stderr, f"{shown}\n{proc.stderr[-2000:]}"
        stray = [ln for ln in proc.stderr.splitlines() if ln.strip() and not ln.startswith("asperity: note:")]
        assert not stray, f"README {kind} step wrote to stderr: {shown}\n{proc.stderr[-2000:]}"
    assert (workdir / "mu.png").exists() and (workdir / "f.csv").exists() and (workdir / "mu_vs_P.csv").exists()
