#!/bin/busybox sh
# SPDX-License-Identifier: Apache-2.0
# /init of the kernel GPIO test's guest: mount what the test needs, create a
# gpio-sim bank with named lines through configfs, run the test program and
# power off. The host script looks for the program's pass marker.
/bin/busybox --install -s /bin
export PATH=/bin
mount -t proc proc /proc
mount -t sysfs sysfs /sys
mount -t devtmpfs dev /dev
mount -t tmpfs tmp /tmp

finish() { echo "guest: $*"; poweroff -f; }

modprobe gpio-sim || finish "GPIO-KERNEL-TEST-ERROR: modprobe gpio-sim failed"
mount -t configfs none /config || finish "GPIO-KERNEL-TEST-ERROR: mounting configfs failed"
sim=/config/gpio-sim/glider
mkdir "$sim" "$sim/bank0"
echo 8 > "$sim/bank0/num_lines"
# The names the board file (boards/gpio/gpio_sim.toml) asks for; 5..7 stay unnamed.
offset=0
for name in LEAK DROP_WEIGHT PUMP_ENABLE VALVE SLIDE_FWD; do
  mkdir "$sim/bank0/line$offset"
  echo "$name" > "$sim/bank0/line$offset/name"
  offset=$((offset + 1))
done
echo 1 > "$sim/live" || finish "GPIO-KERNEL-TEST-ERROR: gpio-sim bank did not go live"
chip="$(cat "$sim/bank0/chip_name")"   # gpiochip0 here; another number on arm64 virt
device="$(cat "$sim/dev_name")"
echo "guest: $(uname -r), gpio-sim bank $chip on $device"
/test/gpio_kernel_test /test/gpio_sim.toml "$chip" "/sys/devices/platform/$device/$chip"
finish "test program exited with $?"
