"""Shared Jinja2 environment and the formatters applied to generated files."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import jinja2

ROOT = Path(__file__).resolve().parent.parent
TEMPLATES = ROOT / "templates"


class ToolError(Exception):
    pass


def environment() -> jinja2.Environment:
    env = jinja2.Environment(
        loader=jinja2.FileSystemLoader(str(TEMPLATES)),
        undefined=jinja2.StrictUndefined,
        trim_blocks=True,
        lstrip_blocks=True,
        keep_trailing_newline=True,
        autoescape=False,
    )
    env.filters["hex2"] = lambda v: "0x%02X" % v
    return env


def _which(name: str, env_var: str) -> str:
    beside = Path(sys.executable).parent / name  # tools installed in the same virtualenv
    exe = os.environ.get(env_var) or (str(beside) if beside.exists() else None) or shutil.which(name)
    if not exe:
        raise ToolError(
            f"'{name}' is not installed (needed to format generated code); run 'make' to set up, or set {env_var}"
        )
    return exe


def _run_all(cmds: list[list[str]], cwd: str) -> None:
    """Runs the formatter commands at the same time (they touch disjoint files); raises on the
    first that failed, after all have ended."""
    procs = [subprocess.Popen(c, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True) for c in cmds]
    results = [(c, p, *p.communicate()) for c, p in zip(cmds, procs)]
    for cmd, proc, out, err in results:
        if proc.returncode != 0:
            raise ToolError(f"{' '.join(cmd[:2])} failed:\n{out}{err}")


def format_files(files: dict[str, str]) -> dict[str, str]:
    """Format generated sources in one batch per tool. Keys are paths relative to generated/."""
    by_tool: dict[str, list[str]] = {"clang": [], "rust": [], "python": []}
    for rel in files:
        ext = Path(rel).suffix
        if ext in (".c", ".h", ".cpp", ".hpp", ".cc"):
            by_tool["clang"].append(rel)
        elif ext == ".rs":
            by_tool["rust"].append(rel)
        elif ext == ".py":
            by_tool["python"].append(rel)
    if not any(by_tool.values()):
        return files
    out = dict(files)
    with tempfile.TemporaryDirectory(prefix="gen-fmt-") as tmp:
        for rel, text in files.items():
            p = Path(tmp, rel)
            p.parent.mkdir(parents=True, exist_ok=True)
            p.write_text(text, encoding="utf-8")
        # One command per tool and batch, all run at once: formatting is most of a regeneration's
        # time, and the clang-format half is split in two so that two cores share it.
        cmds: list[list[str]] = []
        if by_tool["clang"]:
            shutil.copy(ROOT / ".clang-format", Path(tmp, ".clang-format"))
            exe = _which("clang-format", "CLANG_FORMAT")
            clang = by_tool["clang"]
            half = (len(clang) + 1) // 2
            cmds += [[exe, "-i", "--style=file", *batch] for batch in (clang[:half], clang[half:]) if batch]
        if by_tool["rust"]:
            cmds.append([_which("rustfmt", "RUSTFMT"), "--edition", "2021", *by_tool["rust"]])
        if by_tool["python"]:
            shutil.copy(ROOT / "ruff.toml", Path(tmp, "ruff.toml"))
            cmds.append([_which("ruff", "RUFF"), "format", "--quiet", "--config", "ruff.toml", *by_tool["python"]])
        _run_all(cmds, tmp)
        for tool_files in by_tool.values():
            for rel in tool_files:
                out[rel] = Path(tmp, rel).read_text(encoding="utf-8")
    return out


TARGETS_DIR = ROOT / "generator" / "targets"


def runtime_dir(lang: str) -> Path:
    """Where a target's hand-written runtime lives: plain source files, compiled, linted and
    unit-tested in place (generator/targets/<lang>/runtime/)."""
    return TARGETS_DIR / lang / "runtime"


def copy_runtime(lang: str, mapping: dict[str, str], replace: list[tuple[str, str]] | None = None) -> dict[str, str]:
    """The runtime files of a target for one package: {source path under runtime/: destination
    path under generated/}. The text is copied verbatim, except for the plain-text replacements
    `replace` (old, new), applied in order (e.g. a C package's symbol prefix)."""
    out: dict[str, str] = {}
    for src, dest in mapping.items():
        text = (runtime_dir(lang) / src).read_text(encoding="utf-8")
        for old, new in replace or []:
            text = text.replace(old, new)
        out[dest] = text
    return out
