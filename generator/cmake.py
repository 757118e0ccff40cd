"""What the C and C++ packages share of their CMake packaging (docs/packaging.md): the config
package file {pkg}Config.cmake and its version file {pkg}ConfigVersion.cmake, which both back ends
render from one template each to the same bytes so that the two packages of a protocol install
into one tree (find_package({pkg}) then gives {pkg}::c, {pkg}::c_json, {pkg}::c_posix and
{pkg}::cpp, whichever are installed), the pkg-config files, the C package's Cortex-M toolchain
file and both packages' MinGW-w64 (Windows) toolchain file."""

from __future__ import annotations

from generator.render import environment


def pkg_config(package: str, title: str, lang: str) -> list[dict]:
    """The pkg-config files of a package (templates/cmake/pc.in.j2): the C core, JSON and POSIX
    transport libraries, or the C++ library; names as docs/packaging.md lists them."""
    if lang == "c":
        return [
            {
                "name": package,
                "description": f"C99 codec of the {title} protocol (core)",
                "lib": package,
                "requires": None,
            },
            {
                "name": f"{package}-json",
                "description": f"canonical JSON of the {title} protocol (C)",
                "lib": f"{package}_json",
                "requires": package,
            },
            {
                "name": f"{package}-posix",
                "description": f"POSIX TCP and serial transports of the {title} session API (C)",
                "lib": f"{package}_posix",
                "requires": package,
            },
            {
                "name": f"{package}-win32",
                "description": f"Win32 TCP and serial transports of the {title} session API (C)",
                "lib": f"{package}_win32",
                "requires": package,
                "system_libs": "-lws2_32",
            },
        ]
    return [
        {
            "name": f"{package}-cpp",
            "description": f"C++17 codec of the {title} protocol",
            "lib": f"{package}_cpp",
            "requires": None,
        }
    ]


def cmake_package_files(root: str, ctx: dict, pcs: list[dict], toolchains: bool = False) -> dict[str, str]:
    """The CMake config package file and the helper that writes its version file (the same bytes
    from the C and the C++ back end, so that both packages install into one tree), the pkg-config
    helper and the .pc templates of a package, the MinGW-w64 toolchain file; with `toolchains` (the C
    package) the Cortex-M toolchain file."""
    env = environment()
    pkg = ctx["pkg"]
    out = {
        root + f"cmake/{pkg}Config.cmake": env.get_template("cmake/config.cmake.j2").render(ctx),
        root + f"cmake/{pkg}-version-file.cmake": env.get_template("cmake/version-file.cmake.j2").render(ctx),
        root + f"cmake/{pkg}-pkg-config.cmake": env.get_template("cmake/pkg-config.cmake.j2").render(ctx),
    }
    for pc in pcs:
        out[root + f"cmake/{pc['name']}.pc.in"] = env.get_template("cmake/pc.in.j2").render(ctx, pc=pc)
    out[root + "cmake/x86_64-w64-mingw32.cmake"] = env.get_template("cmake/x86_64-w64-mingw32.cmake.j2").render(ctx)
    if toolchains:
        out[root + "cmake/arm-none-eabi.cmake"] = env.get_template("cmake/arm-none-eabi.cmake.j2").render(ctx)
    return out
