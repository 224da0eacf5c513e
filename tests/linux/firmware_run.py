#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""glider-firmware end to end on the build machine: the Modbus actuator
simulator (TCP), a Keller transmitter, GPS and compass on socat pty pairs fed
with good and bad sentences; the firmware runs a few seconds on the demo
mission, gets SIGTERM, must stop cleanly (exit 0) with its flight log, its
loop jitter figures and every sensor's counters.

  firmware_run.py BUILD_DIR SOURCE_DIR

GLIDER_FIRMWARE (a binary) and GLIDER_FIRMWARE_PREFIX (a command before it,
e.g. "qemu-aarch64 -L /") run another
build of the firmware the same way (the arm64 one, for its memory figures).
"""
import os
import re
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time

PROCESSES = []


def fail(message):
    print("FAIL firmware_run: " + message)
    for p in PROCESSES:
        p.kill()
    sys.exit(1)


def start(args, **kwargs):
    p = subprocess.Popen(args, **kwargs)
    PROCESSES.append(p)
    return p


def pty_pair(tmp, name):
    device, glider = os.path.join(tmp, name + "-device"), os.path.join(tmp, name + "-glider")
    start(["socat", "pty,raw,echo=0,link=" + device, "pty,raw,echo=0,link=" + glider],
          stderr=subprocess.DEVNULL)
    for _ in range(500):
        if os.path.exists(device) and os.path.exists(glider):
            return device, glider
        time.sleep(0.01)
    fail("socat did not create the %s pty pair" % name)


def nmea(body, corrupt=False):
    checksum = 0
    for c in body.encode():
        checksum ^= c
    return "$%s*%02X\r\n" % (body, checksum ^ (0x5A if corrupt else 0))


def feeder(device, sentences, stop):
    """Writes the sentences in turn, one every 0.25 s, like a sensor."""
    with open(device, "wb", buffering=0) as port:
        i = 0
        while not stop.is_set():
            port.write(sentences[i % len(sentences)].encode())
            i += 1
            time.sleep(0.25)


def main():
    build, source = sys.argv[1], sys.argv[2]
    firmware = os.environ.get("GLIDER_FIRMWARE", os.path.join(build, "firmware", "linux", "glider-firmware"))
    prefix = os.environ.get("GLIDER_FIRMWARE_PREFIX", "").split()
    with tempfile.TemporaryDirectory() as tmp:
        sim = start([os.path.join(build, "tools", "hardware", "actuator_sim", "glider-actuator-sim"), "--tcp", "127.0.0.1:0"],
                    stdout=subprocess.PIPE, text=True)
        port = re.search(r"serving tcp 127\.0\.0\.1:(\d+)", sim.stdout.readline())
        if not port:
            fail("the actuator simulator did not start")
        gps_device, gps_glider = pty_pair(tmp, "gps")
        compass_device, compass_glider = pty_pair(tmp, "compass")
        depth_device, depth_glider = pty_pair(tmp, "depth")
        keller = start([os.path.join(build, "tests", "linux", "keller_transmitter"), depth_device, "1.06"],
                       stdout=subprocess.PIPE, text=True)
        if "serving" not in keller.stdout.readline():
            fail("the Keller transmitter did not start")
        stop = threading.Event()
        gga = "GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,"
        gps_sentences = [nmea(gga), nmea("GPRMC,123520,A,4807.040,N,01131.010,E,0.0,84.4,230394,003.1,W"),
                         nmea(gga, corrupt=True), "garbage\r\n$GPGGA,1235"]
        compass_sentences = [nmea("PTNTHPR,85.9,N,-0.9,N,0.8,N"), nmea("PTNTHPR,86.0,N,-1.0,N,0.7,N"),
                             nmea("PTNTHPR,86.1,P,-1.0,N,0.7,N")]
        for device, sentences in ((gps_device, gps_sentences), (compass_device, compass_sentences)):
            threading.Thread(target=feeder, args=(device, sentences, stop), daemon=True).start()

        board = os.path.join(tmp, "board.toml")
        with open(board, "w") as f:
            f.write('name = "firmware_run"\n[loop]\nstats_every_s = 1.0\n'
                    '[actuators]\nboard = "%s/boards/actuators/default_modbus.toml"\n'
                    '[gps]\ndevice = "%s"\n[compass]\ndevice = "%s"\n'
                    '[depth]\ndevice = "%s"\n[log]\ndirectory = "%s"\n'
                    % (source, gps_glider, compass_glider, depth_glider, tmp))
        # systemd's side of sd_notify: a datagram socket, and a 2 s watchdog.
        notify = socket.socket(socket.AF_UNIX, socket.SOCK_DGRAM)
        notify.bind(os.path.join(tmp, "notify"))
        notify.settimeout(0.2)
        messages = []

        def collect():
            while not stop.is_set():
                try:
                    messages.append(notify.recv(4096).decode())
                except socket.timeout:
                    pass
        threading.Thread(target=collect, daemon=True).start()
        env = dict(os.environ, NOTIFY_SOCKET=os.path.join(tmp, "notify"), WATCHDOG_USEC="2000000")
        log = os.path.join(tmp, "flight.csv")
        started = time.monotonic()
        fw = start(prefix + [firmware, "--board", board, "--mission", os.path.join(source, "boards/missions/demo_yo.toml"),
                    "--actuators-tcp", "127.0.0.1:" + port.group(1), "--log", log],
                   stderr=subprocess.PIPE, text=True, env=env)
        time.sleep(5.0)
        if fw.poll() is not None:
            print(fw.stderr.read(), end="")
            fail("glider-firmware exited (status %d) before SIGTERM" % fw.returncode)
        with open("/proc/%d/status" % fw.pid) as f:
            memory = dict(line.split(":", 1) for line in f if line.startswith(("VmHWM", "VmRSS")))
        print("firmware memory after 5 s: peak RSS %s, RSS %s" % (memory["VmHWM"].strip(), memory["VmRSS"].strip()))
        fw.send_signal(signal.SIGTERM)
        try:
            _, err = fw.communicate(timeout=5)
        except subprocess.TimeoutExpired:
            fail("glider-firmware did not stop within 5 s of SIGTERM")
        time.sleep(0.3)
        stop.set()
        print(err, end="")
        print("sd_notify messages: " + " | ".join(m.replace("\n", " ") for m in messages))
        print("ran %.1f s wall" % (time.monotonic() - started))
        if fw.returncode != 0:
            fail("exit status %d after SIGTERM" % fw.returncode)
        for pattern, what in [
                (r"stopped by signal", "the stop reason"),
                (r"loop: cycles [5-9], wake-up late mean \d+ us, p50 <= \d+ us, p99 <= \d+ us, max \d+ us", "jitter figures"),
                (r"gps: \d+ bytes, [1-9]\d* sentences used; rejected: [1-9]\d* bad checksum", "GPS used and rejected"),
                (r"compass: \d+ bytes, [1-9]\d* sentences used;.* [1-9]\d* no fix", "compass used and rejected"),
                (r"depth: [1-9]\d* reads; rejected: 0 bus failures", "depth read"),
                (r"log: [5-9] rows written, 0 refused", "log rows"),
                (r"watchdog on \([3-9] pings\)", "watchdog pings")]:
            if not re.search(pattern, err):
                fail("no %s in the output (/%s/)" % (what, pattern))
        if not messages or not messages[0].startswith("READY=1") or messages[-1] != "STOPPING=1" or \
                messages.count("WATCHDOG=1") < 3:
            fail("systemd notifications: expected READY=1, WATCHDOG=1 (3+), STOPPING=1")
        # The two summary lines say the same rows lost (the log's count).
        said = re.search(r"(\d+) log rows lost", err), re.search(r"flight log .*: \d+ rows, (\d+) lost", err)
        if not all(said) or said[0].group(1) != said[1].group(1):
            fail("the summary's rows lost disagree: %s" % [m.group(0) if m else None for m in said])
        with open(log) as f:
            text = f.read()
        # Our writer names itself first: a log without the trailer reads as cut short.
        if not text.startswith("# writer: glider-firmware\n"):
            fail("flight log: the first line is not '# writer: glider-firmware'")
        rows = [line + "\n" for line in text.splitlines() if not line.startswith("#")]
        if not rows[0].startswith("m_present_time,m_depth,") or len(rows) < 6:
            fail("flight log: expected the header and at least 5 rows, got %d lines" % len(rows))
        depth = float(rows[-1].split(",")[1])
        if abs(depth - (1.06 - 1.01325) * 1e5 / (1025 * 9.80665)) > 1e-3:
            fail("flight log depth %.4f m is not the transmitter's" % depth)
        # The Slocum data files (on by default, beside the log): one segment, ended.
        slocum = os.path.join(tmp, "slocum")
        dbd = sorted(n for n in os.listdir(slocum) if n.endswith(".dbd")) if os.path.isdir(slocum) else []
        if len(dbd) != 1 or not open(os.path.join(slocum, dbd[0]), "rb").read().endswith(b"X") or \
                not re.search(r"slocum files .*: 1 segments, .dbd %d cycles, .sbd \d+ cycles, 0 lost" % (len(rows) - 1), err):
            fail("Slocum files: expected one ended .dbd with every row, found %s" % dbd)
    for p in PROCESSES:
        p.terminate()
    print("PASS firmware_run")


if __name__ == "__main__":
    main()
