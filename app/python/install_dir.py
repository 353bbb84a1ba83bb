"""Prints where a package goes under the install prefix given, relative to it, so that the
interpreter running this script imports it from there."""
import sys
import sysconfig


def install_dir(prefix: str) -> str:
    version = f"python{sys.version_info[0]}.{sys.version_info[1]}"
    if "deb_system" in sysconfig.get_scheme_names():
        # Debian: /usr holds the distribution's packages, every other prefix (/usr/local
        # first) the version's dist-packages
        if prefix.rstrip("/") == "/usr":
            return "lib/python3/dist-packages"
        return f"lib/{version}/dist-packages"
    path = sysconfig.get_path("platlib", "posix_prefix", vars={"base": "", "platbase": ""})
    return path.lstrip("/")


if __name__ == "__main__":
    print(install_dir(sys.argv[1] if len(sys.argv) > 1 else sys.prefix))
