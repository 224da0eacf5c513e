#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Runs the GPIO driver's test program on a real Linux kernel: a qemu guest
# (TCG) booting the installed Debian kernel with an initramfs of busybox,
# configfs, the gpio-sim and irq_sim modules and the static test binary.
#
#   run_gpio_kernel_test.sh ARCH CACHE_DIR TEST_BINARY BOARD_TEMPLATE
#
# ARCH x86_64: the installed Debian kernel; aarch64: the same Debian kernel
# version for arm64 (downloaded into the cache), qemu-system-aarch64 -M virt.
#
# Debian builds its kernels without gpio-sim, so its source (and irq_sim's)
# is taken from the linux-source tarball and built out of tree against the
# installed headers, once per kernel version (cached in CACHE_DIR). One
# change is needed: irq_to_desc() is not exported to modules, so irq_sim's
# handle_simple_irq(irq_to_desc(n)) becomes generic_handle_irq(n).
# Exit 0 only when the guest printed the test program's pass marker.
set -euo pipefail

fail() { echo "GPIO-KERNEL-TEST-ERROR: $*" >&2; exit 1; }

[ $# -eq 4 ] || fail "usage: $0 ARCH CACHE_DIR TEST_BINARY BOARD_TEMPLATE"
ARCH="$1" CACHE="$2" TEST_BINARY="$3" BOARD="$4"
case "$ARCH" in x86_64|aarch64) ;; *) fail "no guest set up for $ARCH (x86_64, aarch64)" ;; esac
BOOT_TIMEOUT_S="${GPIO_KERNEL_TIMEOUT_S:-240}"

# The newest installed (amd64) kernel that has its headers (never a
# hard-coded version); the arm64 guest runs the same Debian kernel ABI.
HOST_KVER=""
for image in $(ls -1 /boot/vmlinuz-* 2>/dev/null | sort -rV); do
  candidate="${image#/boot/vmlinuz-}"
  if [ -d "/lib/modules/$candidate/build" ]; then HOST_KVER="$candidate"; break; fi
done
[ -n "$HOST_KVER" ] || fail "no kernel image with headers: install linux-image-amd64 and linux-headers-amd64 (./glider installs them)"
SOURCE_TARBALL="$(ls -1 /usr/src/linux-source-*.tar.xz 2>/dev/null | sort -rV | head -n 1 || true)"

if [ "$ARCH" = x86_64 ]; then
  KVER="$HOST_KVER"
  KIMAGE="/boot/vmlinuz-$KVER"
  KBUILD="/lib/modules/$KVER/build"
  MAKE_ARGS=()
  BUSYBOX=/bin/busybox  # busybox-static's: the guest has no C library
  MODULE_TREE="/lib/modules/$KVER"
  QEMU=(qemu-system-x86_64 -accel tcg -m 512 -smp 1)
  CONSOLE=ttyS0
else
  # Debian's arm64 kernel, its headers (cross-building modules works with the
  # build machine's linux-kbuild, Multi-Arch: foreign) and busybox: the
  # packages are downloaded and unpacked into the cache, not installed.
  KVER="${HOST_KVER%-amd64}-arm64"
  DEBS="$CACHE/$KVER/debs"
  if [ ! -f "$DEBS/root/boot/vmlinuz-$KVER" ]; then
    mkdir -p "$DEBS" && rm -rf "$DEBS/root"
    (cd "$DEBS" && apt-get download "linux-image-$KVER:arm64" "linux-headers-$KVER:arm64" busybox-static:arm64) ||
      fail "apt-get download of the arm64 kernel, headers and busybox failed (dpkg --add-architecture arm64?)"
    for deb in "$DEBS"/*.deb; do dpkg -x "$deb" "$DEBS/root"; done
  fi
  KIMAGE="$DEBS/root/boot/vmlinuz-$KVER"
  KBUILD="$DEBS/root/usr/src/linux-headers-$KVER"
  # Its scripts link is relative to /usr: point it at the build machine's kbuild.
  ln -sfn "$(ls -d /usr/lib/linux-kbuild-*/scripts | sort -rV | head -n 1)" "$KBUILD/scripts"
  MAKE_ARGS=(ARCH=arm64 CROSS_COMPILE=aarch64-linux-gnu-)
  BUSYBOX="$DEBS/root/bin/busybox"
  MODULE_TREE="$DEBS/root/lib/modules/$KVER"
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
  [ -n "$SOURCE_TARBALL" ] || fail "no /usr/src/linux-source-*.tar.xz (package linux-source)"
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
