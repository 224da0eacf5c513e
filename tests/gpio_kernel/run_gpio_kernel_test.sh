#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Runs the GPIO driver's test program on a real Linux kernel: a qemu guest
# (TCG) booting Debian's kernel (downloaded into the cache, not installed) with an initramfs of busybox,
# configfs, the gpio-sim and irq_sim modules and the static test binary.
#
#   run_gpio_kernel_test.sh ARCH CACHE_DIR TEST_BINARY BOARD_TEMPLATE
#
# ARCH x86_64: Debian's amd64 kernel, qemu-system-x86_64; aarch64: the same
# Debian kernel version for arm64, qemu-system-aarch64 -M virt.
#
# Debian builds its kernels without gpio-sim, so its source (and irq_sim's)
# is taken from the linux-source tarball and built out of tree against the
# downloaded headers, once per kernel version (cached in CACHE_DIR). One
# change is needed: irq_to_desc() is not exported to modules, so irq_sim's
# handle_simple_irq(irq_to_desc(n)) becomes generic_handle_irq(n).
# Exit 0 only when the guest printed the test program's pass marker.
set -euo pipefail

fail() { echo "GPIO-KERNEL-TEST-ERROR: $*" >&2; exit 1; }

[ $# -eq 4 ] || fail "usage: $0 ARCH CACHE_DIR TEST_BINARY BOARD_TEMPLATE"
ARCH="$1" CACHE="$2" TEST_BINARY="$3" BOARD="$4"
case "$ARCH" in x86_64|aarch64) ;; *) fail "no guest set up for $ARCH (x86_64, aarch64)" ;; esac
BOOT_TIMEOUT_S="${GPIO_KERNEL_TIMEOUT_S:-240}"

# Debian's current kernel (the version linux-image-amd64 points at), never a
# hard-coded one. Nothing is installed on the host: the kernel image, its
# headers, kbuild, the kernel source and busybox are downloaded with
# `apt-get download` and unpacked with `dpkg-deb -x` into the cache, once
# per kernel version. (A developer's /boot is none of this test's business.)
if [ -n "${GPIO_KERNEL_VERSION:-}" ]; then
  KBASE="$GPIO_KERNEL_VERSION"
else
  KBASE="$(apt-cache depends linux-image-amd64 2>/dev/null | sed -n 's/.*Depends: linux-image-\(.*\)-amd64$/\1/p' | head -n 1)"
fi
[ -n "$KBASE" ] || fail "apt-cache knows no linux-image-amd64 (run apt-get update), or set GPIO_KERNEL_VERSION=6.1.0-NN"
KSERIES="${KBASE%%-*}"; KSERIES="${KSERIES%.*}"   # 6.1.0-56 -> 6.1
if [ "$ARCH" = x86_64 ]; then DEBARCH=amd64; else DEBARCH=arm64; fi
KVER="$KBASE-$DEBARCH"
DEBS="$CACHE/$KVER/debs"
ROOT="$DEBS/root"

fetch() {  # fetch PACKAGE... : apt-get download into $DEBS (update the lists once if asked to)
  (cd "$DEBS" && apt-get download "$@" >/dev/null 2>&1) && return 0
  if [ "$(id -u)" -eq 0 ]; then apt-get update -qq >/dev/null 2>&1 || true; fi
  (cd "$DEBS" && apt-get download "$@") || fail "apt-get download $* failed (apt lists, network, multiarch for :arm64?)"
}
if [ ! -f "$DEBS/unpacked" ]; then
  rm -rf "$DEBS" && mkdir -p "$DEBS"
  echo "downloading Debian's $KVER kernel, headers, kbuild, source and busybox into $DEBS (once)"
  if [ "$ARCH" = x86_64 ]; then
    fetch "linux-image-$KVER" "linux-headers-$KVER" busybox-static
  else
    fetch "linux-image-$KVER:arm64" "linux-headers-$KVER:arm64" busybox-static:arm64
  fi
  # Architecture-independent parts and the build machine's kbuild (Multi-Arch: foreign).
  fetch "linux-headers-$KBASE-common" "linux-kbuild-$KSERIES" "linux-source-$KSERIES"
  for deb in "$DEBS"/*.deb; do dpkg-deb -x "$deb" "$ROOT"; done
  rm -f "$DEBS"/*.deb
  touch "$DEBS/unpacked"
fi
KIMAGE="$ROOT/boot/vmlinuz-$KVER"
KBUILD="$ROOT/usr/src/linux-headers-$KVER"
# The headers' Makefile includes the common headers by absolute path, and its
# scripts/tools links are relative to /usr/src: point all three into the cache.
sed -i "s|^include /usr/src/|include $ROOT/usr/src/|" "$KBUILD/Makefile"
ln -sfn "$ROOT/usr/lib/linux-kbuild-$KSERIES/scripts" "$KBUILD/scripts"
ln -sfn "$ROOT/usr/lib/linux-kbuild-$KSERIES/tools" "$KBUILD/tools"
for common_link in scripts tools; do
  [ -L "$ROOT/usr/src/linux-headers-$KBASE-common/$common_link" ] &&
    ln -sfn "$ROOT/usr/lib/linux-kbuild-$KSERIES/$common_link" "$ROOT/usr/src/linux-headers-$KBASE-common/$common_link"
done
SOURCE_TARBALL="$(ls -1 "$ROOT"/usr/src/linux-source-*.tar.xz 2>/dev/null | sort -rV | head -n 1 || true)"
BUSYBOX="$ROOT/bin/busybox"  # busybox-static's: the guest has no C library
MODULE_TREE="$ROOT/lib/modules/$KVER"
if [ "$ARCH" = x86_64 ]; then
  MAKE_ARGS=()
  QEMU=(qemu-system-x86_64 -accel tcg -m 512 -smp 1)
  CONSOLE=ttyS0
else
  MAKE_ARGS=(ARCH=arm64 CROSS_COMPILE=aarch64-linux-gnu-)
  QEMU=(qemu-system-aarch64 -M virt -cpu cortex-a72 -accel tcg -m 512 -smp 1)
  CONSOLE=ttyAMA0
fi
[ -r "$KIMAGE" ] || fail "$KIMAGE is not readable"
command -v "${QEMU[0]}" >/dev/null || fail "${QEMU[0]} missing (package qemu-system-x86 / qemu-system-arm)"
[ -x "$BUSYBOX" ] || fail "$BUSYBOX missing (package busybox-static)"
CONFIGFS="$(find "$MODULE_TREE/kernel/fs/configfs" -name 'configfs.ko*' 2>/dev/null | head -n 1 || true)"

MODULES="$CACHE/$KVER/modules"
mkdir -p "$MODULES"
if [ ! -f "$MODULES/gpio-sim.ko" ] || [ ! -f "$MODULES/irq_sim.ko" ]; then
  [ -n "$SOURCE_TARBALL" ] || fail "no linux-source-*.tar.xz in $ROOT/usr/src (package linux-source-$KSERIES)"
  echo "building gpio-sim and irq_sim for $KVER from $SOURCE_TARBALL (cached in $MODULES)"
  work="$CACHE/$KVER/src"
  rm -rf "$work" && mkdir -p "$work"
  top="$(basename "$SOURCE_TARBALL" .tar.xz)"
  # Only the three files needed (the whole tree is ~1.4 GB unpacked).
  tar -xJf "$SOURCE_TARBALL" -C "$work" "$top/drivers/gpio/gpio-sim.c" "$top/drivers/gpio/gpiolib.h" \
    "$top/kernel/irq/irq_sim.c" || fail "extracting gpio-sim.c, gpiolib.h and irq_sim.c from $SOURCE_TARBALL"
  find "$work/$top" -name '*.[ch]' -exec mv -t "$work" {} +
  for f in gpio-sim.c gpiolib.h irq_sim.c; do [ -f "$work/$f" ] || fail "$f not found in $SOURCE_TARBALL"; done
  grep -q 'handle_simple_irq(irq_to_desc(irqnum))' "$work/irq_sim.c" ||
    fail "irq_sim.c of this kernel differs from the patched one (handle_simple_irq(irq_to_desc(irqnum)) not found)"
  sed -i 's/handle_simple_irq(irq_to_desc(irqnum))/generic_handle_irq(irqnum)/' "$work/irq_sim.c"
  grep -q MODULE_LICENSE "$work/irq_sim.c" ||
    printf '\n#include <linux/module.h>\nMODULE_LICENSE("GPL");\nMODULE_DESCRIPTION("irq_sim as a module");\n' >> "$work/irq_sim.c"
  echo 'obj-m := gpio-sim.o irq_sim.o' > "$work/Kbuild"
  make -s -C "$KBUILD" M="$work" "${MAKE_ARGS[@]}" modules 2>&1 | grep -v 'Skipping BTF' || true
  [ -f "$work/gpio-sim.ko" ] && [ -f "$work/irq_sim.ko" ] || fail "building the gpio-sim modules failed"
  cp "$work/gpio-sim.ko" "$work/irq_sim.ko" "$MODULES/"
fi

# The initramfs: rebuilt every run (the test binary changes), in a second or two.
ROOTFS="$CACHE/$KVER/rootfs"
rm -rf "$ROOTFS"
mkdir -p "$ROOTFS"/{bin,proc,sys,dev,tmp,config,test} "$ROOTFS/lib/modules/$KVER/extra"
cp "$BUSYBOX" "$ROOTFS/bin/busybox"
cp "$MODULES"/*.ko "$ROOTFS/lib/modules/$KVER/extra/"
[ -n "$CONFIGFS" ] && cp "$CONFIGFS" "$ROOTFS/lib/modules/$KVER/extra/"
cp "$MODULE_TREE"/modules.builtin* "$ROOTFS/lib/modules/$KVER/" 2>/dev/null || true
depmod -b "$ROOTFS" "$KVER"
cp "$TEST_BINARY" "$ROOTFS/test/gpio_kernel_test"
cp "$BOARD" "$ROOTFS/test/gpio_sim.toml"
cp "$(dirname "${BASH_SOURCE[0]}")/guest_init.sh" "$ROOTFS/init"
chmod +x "$ROOTFS/init"
INITRD="$CACHE/$KVER/initramfs.cpio.gz"
(cd "$ROOTFS" && find . | cpio -o -H newc --quiet | gzip -1 > "$INITRD")

LOG="$CACHE/$KVER/guest.log"
echo "booting $KIMAGE in ${QEMU[0]} (TCG), guest log in $LOG"
start_ms=$(($(date +%s%N) / 1000000))
set +e
timeout --kill-after=10 "$BOOT_TIMEOUT_S" "${QEMU[@]}" -nographic -no-reboot \
  -kernel "$KIMAGE" -initrd "$INITRD" -append "console=$CONSOLE panic=-1 quiet" > "$LOG" 2>&1
status=$?
set -e
elapsed_ms=$(($(date +%s%N) / 1000000 - start_ms))
tr -d '\r' < "$LOG" | grep -v '^\[ *[0-9.]*\] ' || true
printf 'qemu boot + test: %d.%03d s wall (exit %d)\n' $((elapsed_ms / 1000)) $((elapsed_ms % 1000)) "$status"
[ $status -ne 124 ] && [ $status -ne 137 ] || fail "the guest did not finish within ${BOOT_TIMEOUT_S} s (timeout)"
grep -q 'GPIO-KERNEL-TESTS PASS' "$LOG" || fail "no pass marker from the guest (see the output above, $LOG)"
echo "PASS gpio.kernel_$ARCH on $KVER"
