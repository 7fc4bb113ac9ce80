#!/usr/bin/env bash
# The README's two commands on Debian 13 ("trixie": deal.II 9.6, OpenMPI 5,
# g++ 14), run by hand from a Debian machine as root; CI stays on Debian 12.
#
#   bash .ci/debian13.sh [--worktree] [--keep-build]
#
# Makes (or reuses) a trixie root with debootstrap (minbase, the Debian
# archive this machine's apt uses), copies the repository into it as
# /root/hemicontact, and runs there, under chroot,
#   bash .ci/quickstart.sh example   then   bash .ci/quickstart.sh test
# printing each command's time and the suite's counts; the logs stay in
# ROOT/root/logs/. Exits non-zero if either command fails.
#
#   --worktree     copy the working tree (uncommitted and untracked files
#                  included) instead of HEAD
#   --keep-build   keep ROOT/root/hemicontact/build from the last run (an
#                  incremental build; the default builds from scratch)
# Environment: HEMICONTACT_TRIXIE_ROOT (default /var/tmp/hemicontact-trixie),
# HEMICONTACT_TRIXIE_MIRROR (default: the first .../debian archive of
# /etc/apt/sources.list*, else http://deb.debian.org/debian).
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
root="${HEMICONTACT_TRIXIE_ROOT:-/var/tmp/hemicontact-trixie}"

worktree=0 keep_build=0
for arg in "$@"; do
  case "$arg" in
    --worktree) worktree=1 ;;
    --keep-build) keep_build=1 ;;
    *) echo "usage: bash .ci/debian13.sh [--worktree] [--keep-build]" >&2; exit 1 ;;
  esac
done
if [ "$(id -u)" -ne 0 ]; then
  echo "debian13.sh: debootstrap, mount and chroot need root" >&2
  exit 1
fi

# the archive this machine installs from (a Debian mirror carries trixie too)
mirror="${HEMICONTACT_TRIXIE_MIRROR:-}"
if [ -z "$mirror" ]; then
  mirror=$(grep -hoE '(https?://[^ ]*/debian)/?( |$)' /etc/apt/sources.list \
             /etc/apt/sources.list.d/*.list /etc/apt/sources.list.d/*.sources \
             2> /dev/null | head -n 1 | tr -d ' ' || true)
  mirror="${mirror%/}"
  mirror="${mirror:-http://deb.debian.org/debian}"
fi

# 1. the root: made once, then reused
if [ ! -x "$root/usr/bin/apt-get" ]; then
  command -v debootstrap > /dev/null ||
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends debootstrap < /dev/null
  echo "debootstrap trixie from $mirror into $root"
  start=$(date +%s)
  debootstrap --variant=minbase trixie "$root" "$mirror" > "$root.debootstrap.log" 2>&1 ||
    { tail -n 20 "$root.debootstrap.log" >&2; exit 1; }
  echo "  $(($(date +%s) - start)) s"
fi
cp /etc/resolv.conf "$root/etc/resolv.conf"

# 2. the repository: HEAD, or the working tree with --worktree
dest="$root/root/hemicontact"
if [ $keep_build -eq 1 ] && [ -d "$dest/build" ]; then
  find "$dest" -mindepth 1 -maxdepth 1 ! -name build -exec rm -rf {} +
else
  rm -rf "$dest"
fi
mkdir -p "$dest" "$root/root/logs"
if [ $worktree -eq 1 ]; then
  # tracked and untracked files, not the ignored ones (build trees)
  (cd "$repo" && git ls-files -z --cached --others --exclude-standard |
     while IFS= read -r -d '' f; do [ -e "$f" ] && printf '%s\0' "$f"; done |
     tar --null -T - -cf -) | tar -xf - -C "$dest"
  echo "copied the working tree of $repo ($(cd "$repo" && git rev-parse --short HEAD) and its changes)"
else
  (cd "$repo" && git archive HEAD) | tar -xf - -C "$dest"
  echo "copied $(cd "$repo" && git rev-parse --short HEAD) of $repo"
fi

# 3. what chroot needs: /proc, /sys, /dev (with /dev/pts and a /dev/shm of
# its own for OpenMPI's shared memory), unmounted on exit in reverse order
mounted=()
cleanup() {
  local i
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do
    umount "${mounted[$i]}" 2> /dev/null || umount -l "${mounted[$i]}" || true
  done
}
trap cleanup EXIT
mount_in_root() { # mount_in_root TARGET MOUNT-ARGUMENTS...
  local target="$root/$1"
  shift
  mkdir -p "$target"
  mount "$@" "$target"
  mounted+=("$target")
}
mount_in_root proc -t proc proc
mount_in_root sys -t sysfs sysfs
mount_in_root dev --bind /dev
mount_in_root dev/pts --bind /dev/pts
mount_in_root dev/shm -t tmpfs tmpfs

# a reused root may hold an install that was interrupted
chroot "$root" /usr/bin/dpkg --configure -a > /dev/null

# 4. the README's two commands, in a newcomer's order, timed
status=0
for command in example test; do
  log="$root/root/logs/$command.log"
  echo "== bash .ci/quickstart.sh $command (log: $log)"
  start=$(date +%s)
  rc=0
  chroot "$root" /usr/bin/env -i HOME=/root PATH=/usr/sbin:/usr/bin:/sbin:/bin \
    LANG=C.UTF-8 TERM=dumb \
    /bin/bash -c "cd /root/hemicontact && bash .ci/quickstart.sh $command" \
    > "$log" 2>&1 || rc=$?
  seconds=$(($(date +%s) - start))
  [ $rc -eq 0 ] || status=1
  if [ "$command" = test ]; then
    grep -E "tests passed|The following tests|^[[:space:]]+[0-9]+ - " "$log" || true
    grep -E "^Total Test time" "$log" || true
  else
    tail -n 3 "$log"
  fi
  echo "== $command: exit $rc in $((seconds / 60)) min $((seconds % 60)) s"
done
exit $status
