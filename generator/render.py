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


def _run(cmd: list[str], cwd: str) -> None:
    proc = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True)
    if proc.returncode != 0:
        raise ToolError(f"{' '.join(cmd[:2])} failed:\n{proc.stdout}{proc.stderr}")


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
        if by_tool["clang"]:
            shutil.copy(ROOT / ".clang-format", Path(tmp, ".clang-format"))
            exe = _which("clang-format", "CLANG_FORMAT")
            for i in range(0, len(by_tool["clang"]), 200):
                _run([exe, "-i", "--style=file", *by_tool["clang"][i : i + 200]], tmp)
        if by_tool["rust"]:
            exe = _which("rustfmt", "RUSTFMT")
            for i in range(0, len(by_tool["rust"]), 200):
                _run([exe, "--edition", "2021", *by_tool["rust"][i : i + 200]], tmp)
        if by_tool["python"]:
            exe = _which("ruff", "RUFF")
            shutil.copy(ROOT / "ruff.toml", Path(tmp, "ruff.toml"))
            _run([exe, "format", "--quiet", "--config", "ruff.toml", *by_tool["python"]], tmp)
        for tool_files in by_tool.values():
            for rel in tool_files:
                out[rel] = Path(tmp, rel).read_text(encoding="utf-8")
    return out
