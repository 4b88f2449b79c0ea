#!/usr/bin/env bash
# fresh-check.sh [COMMAND] — run COMMAND (default: bash scripts/test.sh) in a clean clone of
# this checkout's HEAD inside a bare Debian 12 root (debootstrap --variant=minbase with git
# and ca-certificates only), as root, with CI=true: the way a new user's machine starts, so
# an install step that only the developer's machine had shows up as a failure. A maintainer
# runs it before a release and after changing what a suite needs (scripts/setup.sh's
# package lists, web/, python/): about 25 minutes on 2 cores, most of it apt and the build;
# not part of CI. Needs root, network and debootstrap (installed if missing).
# RELCOL_FRESH_BASE=DIR keeps the debootstrap root there to be reused by later runs
# (default: made afresh in a temporary folder and removed). The log is kept and its path
# printed; the exit status is COMMAND's (2: the root could not be made).
set -uo pipefail
src=$(git -C "$(dirname "$0")" rev-parse --show-toplevel) || { echo "fresh-check: not in a git checkout" >&2; exit 2; }
cmd=${1:-bash scripts/test.sh}
[ "$(id -u)" -eq 0 ] || { echo "fresh-check: needs root (debootstrap, chroot, mount)" >&2; exit 2; }
[ -z "$(git -C "$src" status --porcelain --untracked-files=no)" ] ||
    echo "fresh-check: uncommitted changes are not checked (it clones HEAD)" >&2

work=$(mktemp -d /tmp/relcol-fresh.XXXXXX)
root="$work/root"
log="$(mktemp /tmp/relcol-fresh-log.XXXXXX)"
mounted=()
cleanup() {
    local m
    for m in "${mounted[@]}"; do umount "$m" 2>/dev/null || umount -l "$m" 2>/dev/null; done
    # only remove the root once nothing is mounted inside it
    if ! grep -q " $root/" /proc/mounts; then rm -rf "$work"; fi
}
trap cleanup EXIT INT TERM

base=${RELCOL_FRESH_BASE:-}
if [ -n "$base" ] && [ -f "$base/.relcol-fresh-ready" ]; then
    cp -a "$base" "$root"
else
    command -v debootstrap >/dev/null ||
        DEBIAN_FRONTEND=noninteractive apt-get install -y -qq debootstrap >/dev/null ||
        { echo "fresh-check: cannot install debootstrap" >&2; exit 2; }
    mirror=$(awk '/^URIs:/{print $2; exit}' /etc/apt/sources.list.d/debian.sources 2>/dev/null)
    [ -n "$mirror" ] || mirror=$(awk '/^deb /{print $2; exit}' /etc/apt/sources.list 2>/dev/null)
    [ -n "$mirror" ] || mirror=http://deb.debian.org/debian
    echo "fresh-check: debootstrap bookworm from $mirror (a few minutes)" >&2
    debootstrap --variant=minbase --include=git,ca-certificates bookworm "$root" "$mirror" \
        >"$log" 2>&1 || { echo "fresh-check: debootstrap failed: $log" >&2; exit 2; }
    # the host's apt sources (security updates), as a user's installed system has them
    cp /etc/apt/sources.list.d/debian.sources "$root/etc/apt/sources.list.d/" 2>/dev/null || true
    touch "$root/.relcol-fresh-ready"
    if [ -n "$base" ]; then rm -rf "$base"; cp -a "$root" "$base"; fi
fi

for m in proc dev sys; do
    mount --bind "/$m" "$root/$m" || { echo "fresh-check: cannot mount /$m" >&2; exit 2; }
    mounted=("$root/$m" "${mounted[@]}")
done
cp /etc/resolv.conf "$root/etc/resolv.conf" 2>/dev/null || true
git clone -q "$src" "$root/root/project" || { echo "fresh-check: git clone failed" >&2; exit 2; }

echo "fresh-check: running '$cmd' in the bare root; log $log" >&2
chroot "$root" /usr/bin/env -i HOME=/root PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
    CI=true bash -c "cd /root/project && $cmd" >>"$log" 2>&1
rc=$?
echo "fresh-check: exit $rc; log $log"
tail -n 5 "$log"
exit $rc
