#!/usr/bin/env bash
# Times `make demo` as a new user meets it: a minimal Debian 12 (debootstrap --variant=minbase)
# in a chroot stands for the fresh machine, a clean clone of HEAD is put in it, and the clock runs
# from `apt-get install make` to the printed report page. Apt, configure + build and the demo
# itself are timed apart (install-deps.sh --demo first, then make demo, which finds its packages
# present). Needs root (debootstrap, chroot, mounts) and the Debian mirror; about 5 minutes on
# 2 cores. Run it on a quiet machine: the build is most of the time.
# Usage: sudo scripts/fresh_machine_demo.sh [OUT_JSON]   (default results/fresh_demo.json)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/results/fresh_demo.json}
[[ $(id -u) -eq 0 ]] || { echo "fresh_machine_demo: needs root (debootstrap, chroot)" >&2; exit 2; }
command -v debootstrap >/dev/null || apt-get -o DPkg::Lock::Timeout=600 install -y -q debootstrap

jail=$(mktemp -d /var/tmp/gaitopt-fresh.XXXXXX)
cleanup() {
  umount "$jail/dev" "$jail/proc" 2>/dev/null || true
  rm -rf --one-file-system "$jail"
}
trap cleanup EXIT

echo "fresh_machine_demo: a minimal Debian 12 in $jail (not timed)"
debootstrap --variant=minbase bookworm "$jail" http://deb.debian.org/debian >/dev/null
cat >"$jail/etc/apt/sources.list" <<'EOF'
deb http://deb.debian.org/debian bookworm main
deb http://deb.debian.org/debian bookworm-updates main
deb http://deb.debian.org/debian-security bookworm-security main
EOF
cp /etc/resolv.conf "$jail/etc/resolv.conf"
mount -t proc proc "$jail/proc"
mount --bind /dev "$jail/dev"
git clone -q "$root" "$jail/opt/gaitopt"
commit=$(git -C "$root" rev-parse --short HEAD)  # the chroot has no git: make demo needs none

echo "fresh_machine_demo: apt, build and demo in the chroot (timed)"
chroot "$jail" /usr/bin/env COMMIT="$commit" /bin/bash -euo pipefail -c '
  export DEBIAN_FRONTEND=noninteractive
  cd /opt/gaitopt
  t0=$(date +%s.%N)
  apt-get -o DPkg::Lock::Timeout=600 update -q >/tmp/demo.log 2>&1
  apt-get -o DPkg::Lock::Timeout=600 install -y -q make >>/tmp/demo.log 2>&1
  bash scripts/install-deps.sh --demo >>/tmp/demo.log 2>&1
  t1=$(date +%s.%N)
  make demo >>/tmp/demo.log 2>&1
  t2=$(date +%s.%N)
  test -s results/walk_opt_mu2004_computed_torque/report.html
  build=$(awk "NR > 1 && \$2 > m { m = \$2 } END { print m / 1000 }" build/.ninja_log)
  python3 - "$t0" "$t1" "$t2" "$build" "$COMMIT" "$(nproc)" <<"PY" >/tmp/fresh.json
import json, sys, time
t0, t1, t2, build = map(float, sys.argv[1:5])
print(json.dumps({
    "commit": sys.argv[5], "cpus": int(sys.argv[6]),
    "date": time.strftime("%Y-%m-%d", time.gmtime(t0)),
    "machine": "Debian 12 minbase chroot (debootstrap), packages from deb.debian.org",
    "apt_s": round(t1 - t0, 1), "build_s": round(build, 1),
    "configure_and_demo_s": round(t2 - t1 - build, 1), "total_s": round(t2 - t0, 1),
    "report_page": "results/walk_opt_mu2004_computed_torque/report.html"}, indent=2))
PY
' || { tail -30 "$jail/tmp/demo.log" >&2; exit 1; }
cp "$jail/tmp/fresh.json" "$out"
cat "$out"
