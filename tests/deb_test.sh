#!/usr/bin/env bash
# The Debian package installs and runs on a clean Debian 12: `cpack -G DEB` from the build
# folder, a minimal Debian 12 made by debootstrap in a temporary folder, the package installed
# there with apt-get (which must find every dependency the package declares) by the setup.sh of
# an exported Gradescope autograder, every problem of the catalog solved by the installed
# program, with nothing of the build machine in reach, and the autograder's run_autograder
# grading a submission there.
# Usage: deb_test.sh BUILD_DIR. Exit 77 (reported as skipped) without root, debootstrap or a
# way to mount /proc in the root (the program finds its data through /proc/self/exe).
set -euo pipefail
build="$(cd "$1" && pwd)"
skip() { echo "deb test skipped: $*"; exit 77; }
[[ $(id -u) -eq 0 ]] || skip "needs root (debootstrap, chroot)"
command -v debootstrap >/dev/null || skip "needs debootstrap (scripts/setup --tests installs it)"

work="$(mktemp -d /tmp/wobble-deb.XXXXXX)"
root="$work/root"
cleanup() {
  if mountpoint -q "$root/proc" 2>/dev/null; then umount "$root/proc"; fi
  rm -rf "$work"
}
trap cleanup EXIT

cpack -G DEB --config "$build/CPackConfig.cmake" -B "$work/pkg" >"$work/cpack.log" 2>&1 ||
  { cat "$work/cpack.log"; exit 1; }
deb="$(ls "$work"/pkg/wobble_*.deb)"
depends="$(dpkg-deb -f "$deb" Depends)"
echo "package: $(basename "$deb"), $(du -h "$deb" | cut -f1); Depends: $depends"
# The last two from the module loaded on demand (lib/wobble/wobble-on-demand.so). GiNaC, CLN,
# GMP, GSL, SUNDIALS and libedit are in the program (linked from their static archives), so not
# among them.
for lib in libfmt9 libtomlplusplus3 libzip4 libcpp-httplib0.11; do
  [[ "$depends" == *"$lib"* ]] || { echo "the package does not declare $lib"; exit 1; }
done

debootstrap --variant=minbase bookworm "$root" http://deb.debian.org/debian >"$work/debootstrap.log" 2>&1 ||
  { tail -20 "$work/debootstrap.log"; exit 1; }
mount -t proc proc "$root/proc" 2>/dev/null || skip "cannot mount /proc in the clean root"
cp /etc/resolv.conf "$root/etc/resolv.conf"
in_root() { chroot "$root" env -i PATH=/usr/bin:/bin HOME=/root "$@"; }
# Installed as a Gradescope autograder installs it: the exported zip's setup.sh, laid out as
# Gradescope lays it out (/autograder/source), installs the package with apt-get.
"$build/wobble" export gradescope four-masses --deb "$deb" --out "$work/autograder.zip" >/dev/null
python3 - "$work/autograder.zip" "$root/autograder/source" <<'PY'
import os, sys, zipfile
with zipfile.ZipFile(sys.argv[1]) as z:
    for info in z.infolist():
        z.extract(info, sys.argv[2])
        os.chmod(os.path.join(sys.argv[2], info.filename), (info.external_attr >> 16) & 0o777)
PY
in_root bash /autograder/source/setup.sh >"$work/install.log" 2>&1 || { tail -20 "$work/install.log"; exit 1; }

[[ "$(in_root sh -c 'command -v wobble')" == /usr/bin/wobble ]]
in_root wobble solve flying-plate >"$work/key.txt"
head -1 "$work/key.txt"
status=0
for id in $(in_root wobble list | awk '/^problems/ {on = 1; next} /^[a-z]/ {on = 0} on {print $1}'); do
  in_root wobble solve "$id" >/dev/null || { echo "installed wobble cannot solve $id"; status=1; }
done
in_root wobble keys --check >"$work/keys.txt" || status=1
tail -1 "$work/keys.txt"
in_root wobble check flying-plate a --name I0 --answer "m*R^2/4" || status=1
# The module, loaded from /usr/lib/wobble by the command that needs it.
in_root wobble export gradescope flying-plate --deb "/autograder/source/$(basename "$deb")" \
  --out /tmp/again.zip || { echo "installed wobble cannot write a zip"; status=1; }
# The autograder grades a submission of the key's answers with the installed program.
mkdir -p "$root/autograder/submission"
"$build/wobble" solve four-masses --format json | python3 -c '
import json, sys
key = json.load(sys.stdin)
for p in key["parts"]:
    for a in p["answers"]:
        print("%s = %s %s" % (a["name"], json.dumps(a["value"]), a["unit"]))
' >"$root/autograder/submission/answers.txt"
in_root /autograder/source/run_autograder
python3 -c '
import json, sys
r = json.load(open(sys.argv[1]))
print("autograder in the clean root: score %s of %d" % (r["score"], len(r["tests"])))
sys.exit(0 if r["score"] == len(r["tests"]) == 3 else 1)
' "$root/autograder/results/results.json" || status=1
exit $status
