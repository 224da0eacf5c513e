#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""A scripted Slocum glider calling a shore station over TCP (RUDICS style).

It connects, prints a surface dialog (tests/shore/data/surface_dialog.txt) and
the GliderDOS prompt, then answers what the shore types as the console does:
echo, whoru -> "Vehicle Name:", `send PATTERNS` -> Zmodem send of its files
by Debian's sz, `zr` -> Zmodem receive by rz, anything else -> the prompt
again. It records what it was told in --record (one JSON line per command).

Faults: --drop-after BYTES closes the connection in the middle of its Zmodem
send; --no-name never says its name; --garbage prints binary junk and an
overlong line before the dialog.
"""
import argparse
import glob
import json
import os
import socket
import subprocess
import sys
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--port", type=int, required=True)
    ap.add_argument("--name", default="unit_345")
    ap.add_argument("--files", help="the glider's data folder (what `send` sends from)")
    ap.add_argument("--inbox", help="where files received by zr go")
    ap.add_argument("--record", help="JSON lines: what the shore typed")
    ap.add_argument("--drop-after", type=int, default=-1, help="hang up after this many Zmodem bytes sent")
    ap.add_argument("--no-name", action="store_true")
    ap.add_argument("--garbage", action="store_true")
    ap.add_argument("--hangup-after-dialog", action="store_true", help="print the dialog, no prompt, hang up")
    ap.add_argument("--idle-hangup", type=float, default=3.0, help="seconds without input before hanging up")
    ap.add_argument("--prompt", default="GliderDos N -1 >")
    args = ap.parse_args()
    Glider(args).run()


class Glider:
    def __init__(self, args):
        self.args = args
        self.sock = socket.create_connection(("127.0.0.1", args.port), timeout=10)
        self.sock.settimeout(args.idle_hangup)
        self.record = open(args.record, "a") if args.record else None

    def say(self, text):
        self.sock.sendall(text.encode("latin-1"))

    def note(self, **what):
        if self.record:
            self.record.write(json.dumps(what) + "\n")
            self.record.flush()

    def dialog(self):
        with open(os.path.join(HERE, "data", "surface_dialog.txt")) as f:
            text = f.read()
        name = "" if self.args.no_name else self.args.name
        lines = [l for l in text.replace("@NAME@", name).splitlines()
                 if not (self.args.no_name and "Vehicle Name" in l)]
        self.say("\r\n".join(lines) + "\r\n")

    def read_command(self):
        """One typed line (up to CR); None when the shore hangs up or stays silent."""
        data = b""
        while True:
            try:
                c = self.sock.recv(1)
            except socket.timeout:
                return None
            if not c:
                return None
            if c == b"\x12":  # Ctrl-R: resume the mission (dive)
                return "^R"
            if c == b"\r":
                return data.decode("latin-1")
            if c != b"\n":
                data += c

    def run(self):
        if self.args.garbage:
            self.say("\x00\xff\x1b[2J junk \x07\r\n")
            self.say("X" * 100000 + "\r\n")
        self.dialog()
        if self.args.hangup_after_dialog:
            self.sock.close()
            return
        self.say(self.args.prompt)
        while True:
            command = self.read_command()
            if command is None:
                break
            self.say(command + "\r\n")  # the console's echo
            self.note(command=command)
            words = command.split()
            if command == "^R":
                self.say("Resuming mission\r\n")
                break
            if words and words[0] == "whoru":
                if not self.args.no_name:
                    self.say("Vehicle Name: %s\r\n" % self.args.name)
            elif words and words[0] in ("send", "s"):
                if not self.send(words[1:]):
                    return  # hung up mid-transfer
            elif words and words[0] == "zr":
                self.receive()
            elif words:
                self.say("%s: done\r\n" % words[0])
            self.say(self.args.prompt)
        self.sock.close()

    def send(self, patterns):
        names = sorted({os.path.basename(p) for pat in patterns
                        for p in glob.glob(os.path.join(self.args.files or ".", pat))})
        if not names:
            self.say("No files found\r\n")
            return True
        self.note(sending=names)
        if self.args.drop_after < 0:
            self.sock.settimeout(None)
            rc = subprocess.call(["sz", "-b", "-q"] + names, cwd=self.args.files,
                                 stdin=self.sock.fileno(), stdout=self.sock.fileno(), stderr=subprocess.DEVNULL)
            self.sock.settimeout(self.args.idle_hangup)
            self.note(sz_exit=rc)
            return True
        # Carrier drop: pump sz's output and cut the call after N bytes.
        self.sock.settimeout(None)
        sz = subprocess.Popen(["sz", "-b", "-q"] + names, cwd=self.args.files, stdin=subprocess.PIPE,
                              stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)

        def upstream():
            try:
                while True:
                    d = self.sock.recv(4096)
                    if not d:
                        break
                    sz.stdin.write(d)
                    sz.stdin.flush()
            except (OSError, ValueError):
                pass
        threading.Thread(target=upstream, daemon=True).start()
        sent = 0
        while sent < self.args.drop_after:
            d = os.read(sz.stdout.fileno(), min(4096, self.args.drop_after - sent))
            if not d:
                break
            self.sock.sendall(d)
            sent += len(d)
        self.note(dropped_after=sent)
        self.sock.shutdown(socket.SHUT_RDWR)
        self.sock.close()
        sz.kill()
        sz.wait()
        return False

    def receive(self):
        os.makedirs(self.args.inbox, exist_ok=True)
        self.sock.settimeout(None)
        rc = subprocess.call(["rz", "-b", "-q", "-y"], cwd=self.args.inbox,
                             stdin=self.sock.fileno(), stdout=self.sock.fileno(), stderr=subprocess.DEVNULL)
        self.sock.settimeout(self.args.idle_hangup)
        self.note(rz_exit=rc, inbox=sorted(os.listdir(self.args.inbox)))


if __name__ == "__main__":
    main()
