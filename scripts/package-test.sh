#!/usr/bin/env bash
# Builds Pineda's Debian package and tries it in a clean Debian 12 root (needs root and Debian's
# archive): installs it beside Mesa, runs glxinfo (under Xvfb) and eglinfo through libglvnd with
# Pineda as the vendor, checks that Mesa stays the default and its files untouched, removes the
# package and checks that the system is as it was.
#   scripts/package-test.sh [BUILD_DIR]   (default build-deb, libraries only)
# A BUILD_DIR that is already built (scripts/test.sh passes its own) is reused: it is
# configured for the prefix /usr only while the package is made (the prefix changes no
# compiled file, only where files install), then given its own prefix back.
# The clean root is a copy of /var/tmp/fresh-bookworm (made by debootstrap --variant=minbase
# if missing, as ../shared/tools/fresh-machine.sh makes it).
set -euo pipefail
root_dir=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root_dir/build-deb}

"$root_dir/scripts/install-deps.sh"
# cpack's DEB generator runs dpkg-shlibdeps (dpkg-dev), which needs `file`; the clean root
# comes from debootstrap.
missing=()
for p in file dpkg-dev debootstrap; do
  dpkg-query -W -f='${Status}' "$p" 2> /dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  apt-get update -q > /dev/null
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}" > /dev/null
fi
fail() {
  echo "FAIL: $*"
  exit 1
}
log=$build/package-build.log
own_prefix=$(sed -n 's/^CMAKE_INSTALL_PREFIX:PATH=//p' "$build/CMakeCache.txt" 2> /dev/null || true)
new_build=()
[ -n "$own_prefix" ] || new_build=(-DCMAKE_BUILD_TYPE=Release -DPINEDA_TESTS=OFF)
mkdir -p "$build"
{
  cmake -S "$root_dir" -B "$build" -DCMAKE_INSTALL_PREFIX=/usr "${new_build[@]}" &&
    cmake --build "$build" -j"$(nproc)" &&
    (cd "$build" && rm -f pineda_*.deb && cpack -G DEB) &&
    if [ -n "$own_prefix" ] && [ "$own_prefix" != /usr ]; then
      cmake -S "$root_dir" -B "$build" -DCMAKE_INSTALL_PREFIX="$own_prefix"
    fi
} > "$log" 2>&1 || { tail -n 30 "$log"; fail "building the package (log: $log)"; }
deb=$(ls "$build"/pineda_*_amd64.deb)
echo "== package: $deb"
dpkg-deb --info "$deb" | sed -n 's/^ \(Package\|Version\|Architecture\|Depends\):/\1:/p'

base=/var/tmp/fresh-bookworm
if [ ! -x "$base/bin/bash" ]; then
  # Debian's mirror where sources are in deb822 form; a debootstrap root has none (the default then).
  mirror=$(sed -n "s/^URIs: //p" /etc/apt/sources.list.d/debian.sources 2> /dev/null | head -n 1 || true)
  debootstrap --variant=minbase bookworm "$base" ${mirror:+"$mirror"} > /dev/null
fi
chroot_dir=$(mktemp -d -p /var/tmp pineda-package.XXXXXX)
cp -a "$base/." "$chroot_dir/"
cp /etc/resolv.conf "$chroot_dir/etc/resolv.conf" 2> /dev/null || true
cp "$deb" "$chroot_dir/tmp/"
mount --bind /proc "$chroot_dir/proc"
mount --bind /dev "$chroot_dir/dev"
mount --bind /sys "$chroot_dir/sys"
cleanup() {
  for m in proc dev sys; do
    umount "$chroot_dir/$m" 2> /dev/null || umount -l "$chroot_dir/$m" 2> /dev/null || true
  done
  for m in proc dev sys; do
    mountpoint -q "$chroot_dir/$m" && { echo "left $chroot_dir: $m still mounted" >&2; return; }
  done
  rm -rf --one-file-system "$chroot_dir"
  rm -f "$chroot_dir.before" "$chroot_dir.after"
}
trap cleanup EXIT

in_root() {
  chroot "$chroot_dir" /usr/bin/env -i HOME=/root PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
    DEBIAN_FRONTEND=noninteractive XDG_RUNTIME_DIR=/tmp bash -c "$1"
}

# Every file, link and folder of the system, but the package manager's own records, logs and caches.
snapshot='find / -xdev \( -path /proc -o -path /sys -o -path /dev -o -path /tmp -o -path /root \
  -o -path /run -o -path /var/lib/dpkg -o -path /var/lib/apt -o -path /var/log \
  -o -path /var/cache \) -prune -o -print | sort'
xvfb='xvfb-run -a -s "-screen 0 1280x1024x24 -noreset"'
glvnd_packages='libglvnd0 libgl1 libglx0 libegl1 libglx-mesa0 libegl-mesa0 libgl1-mesa-dri'

echo "== clean Debian 12 root: apt-get install mesa-utils xvfb xauth"
# apt_in_root ARGS: apt-get in the root, its chatter kept for a failure.
apt_in_root() {
  in_root "apt-get -y -q $* > /tmp/apt.log 2>&1" || { tail -n 20 "$chroot_dir/tmp/apt.log"; fail "apt-get $*"; }
}
apt_in_root update
apt_in_root install --no-install-recommends mesa-utils xvfb xauth
in_root "$snapshot" > "$chroot_dir.before"

echo "== dpkg -L pineda before installing"
in_root 'dpkg -L pineda 2>&1 || true'
echo "== apt-get install ./$(basename "$deb")"
apt_in_root install --no-install-recommends "/tmp/$(basename "$deb")"
echo "== dpkg -L pineda"
in_root 'dpkg -L pineda'

echo "== every file named *pineda* belongs to the package (ldconfig made none of its own)"
unowned=$(in_root 'find / -xdev -name "*pineda*" -not -path "/tmp/*" -not -path "/var/lib/dpkg/*" |
  while read -r f; do dpkg -S "$f" > /dev/null 2>&1 || echo "$f"; done')
[ -z "$unowned" ] || fail "files no package owns: $unowned"
echo "== Mesa's and libglvnd's files untouched (dpkg --verify)"
changed=$(in_root "dpkg --verify $glvnd_packages")
[ -z "$changed" ] || fail "changed: $changed"

echo "== glxinfo -B, __GLX_VENDOR_LIBRARY_NAME=pineda"
out=$(in_root "$xvfb env __GLX_VENDOR_LIBRARY_NAME=pineda glxinfo -B") || fail "glxinfo: $out"
echo "$out" | grep 'OpenGL \(vendor\|renderer\|version\) string'
echo "$out" | grep -q '^OpenGL vendor string: Pineda$' || fail "glxinfo's vendor is not Pineda"
echo "== eglinfo, __EGL_VENDOR_LIBRARY_FILENAMES=/usr/share/pineda/egl_vendor.d/50_pineda.json"
out=$(in_root "$xvfb env __EGL_VENDOR_LIBRARY_FILENAMES=/usr/share/pineda/egl_vendor.d/50_pineda.json eglinfo") ||
  fail "eglinfo: $out"
echo "$out" | grep '^[A-Za-z0-9]* platform:\|EGL vendor string\|OpenGL compatibility profile renderer'
# eglinfo_vendor OUTPUT PLATFORM: the EGL vendor string eglinfo printed for the platform.
eglinfo_vendor() {
  echo "$1" | sed -n "/^$2 platform:/,/^[A-Za-z0-9]* platform:/p" | sed -n 's/^EGL vendor string: //p'
}
for platform in X11 Surfaceless; do
  [ "$(eglinfo_vendor "$out" $platform)" = Pineda ] || fail "eglinfo's $platform vendor is not Pineda"
done
echo "== pineda-run glxinfo -B (the installed pineda-run takes the vendor way)"
out=$(in_root "$xvfb pineda-run glxinfo -B") || fail "pineda-run glxinfo: $out"
echo "$out" | grep -q '^OpenGL vendor string: Pineda$' || fail "pineda-run glxinfo: not Pineda"
echo "OpenGL vendor string: Pineda"
echo "== without the variables, Mesa stays the default"
out=$(in_root "$xvfb glxinfo -B") || fail "glxinfo: $out"
echo "$out" | grep '^OpenGL vendor string'
if echo "$out" | grep -q '^OpenGL vendor string: Pineda'; then
  fail "glxinfo without the variable runs Pineda"
fi
# Mesa's eglinfo exits non-zero here: its GBM platform finds no /dev/dri.
out=$(in_root "$xvfb eglinfo" || true)
for platform in X11 Surfaceless; do
  vendor=$(eglinfo_vendor "$out" $platform)
  echo "$platform platform: EGL vendor string: $vendor"
  [ "$vendor" = "Mesa Project" ] || fail "eglinfo's $platform vendor without the variable is '$vendor'"
done

echo "== apt-get purge --autoremove pineda (and the libraries it alone pulled in)"
apt_in_root purge --autoremove pineda
echo "== dpkg -L pineda after removing"
in_root 'dpkg -L pineda 2>&1 || true'
in_root "$snapshot" > "$chroot_dir.after"
diff "$chroot_dir.before" "$chroot_dir.after" ||
  fail "the files above differ from before the package was installed"
echo "no file added, changed in name or left behind; Mesa's files verified"
echo PASS
