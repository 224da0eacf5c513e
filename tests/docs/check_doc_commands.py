#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Every command line shown in README.md and docs/*.md runs as documented.

The commands are read from the markdown itself, so a doc cannot drift from
the programs again:
  - in fenced sh/bash/shell blocks and indented (four-space) code blocks, every line that starts (after an optional
    `$ ` prompt) with `./glider`, `glider-...` or `build/release/...`; in
    untagged blocks (transcripts), the `$ `-prompted ones;
  - in the text, every `./glider ...` code span: they are the commands and
    synopses of the entry point (`./glider convert [--cache DIR] FILE|DIR...`).
A synopsis is instantiated as written, in its order: every optional part
included, the first of each alternative, one of each repeat, each
placeholder (FILE, DIR, LOG.csv, N, ...) replaced by a small input from
PLACEHOLDERS below. Each command runs in a scratch copy of the source tree
(symbolic links to its folders, its own empty build/ for what the commands
write there, so a run leaves the checkout as it was and a second run finds
no results of the first) with the CTest build's programs (GLIDER_NO_BUILD=1: ./glider neither builds nor installs),
bounded in time, and must exit 0 (3 for a flight that ended in an abort, as
README's exit codes say). Options named in `glider-...` code spans of the
text must exist in that program's --help.

A command that cannot run here (hours long, a server that runs until
stopped, the CI itself, hardware) is marked in the doc, visibly in its source,
by `<!-- doc-test: skip REASON -->` on its line (for a fenced block: on the
line before the block); `<!-- doc-test: skip `COMMAND` REASON -->` skips only
the commands that start with COMMAND. The skips are counted and printed with
their reasons.

A mark applies to every occurrence of the same command in every doc.

  check_doc_commands.py SOURCE_DIR BUILD_DIR DOC.md [--list]
"""
import glob
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import time

TIMEOUT_S = 50  # per command
# Programs that serve until stopped: started in the background, alive and answering after SERVER_CHECK_S is
# their pass; in a transcript block they serve the block's later commands (docs/bench.md's session).
SERVERS = ("./glider actuator-sim", "./glider plant", "./glider shore serve")
SERVER_CHECK_S = 2.0
PROGRAM = r"(?:\./glider|glider-[a-z-]+|build/release/\S+)"
SKIP = re.compile(r"<!--\s*doc-test:\s*skip\s+(.*?)\s*-->")
PLACEHOLDER = re.compile(r"[A-Z][A-Z0-9_]*")

# Small inputs for the placeholders, by (command, option before it, placeholder), most specific first:
# command is `./glider SUB` (or the program name), option None for a positional. {tmp}: a fresh directory.
COMET_CSV = "tests/data/real/comet-2019-222-02-154.csv"
COMET_DBD = "tests/data/real/dbd/comet-2019/comet-2019-222-02-154.dbd"
PLACEHOLDERS = {
    ("./glider sil", None, "MISSION.mi"): "boards/missions/comet-nsb3/missions/nsb3.mi",
    ("./glider sil", "--vehicle", "FILE"): "boards/vehicles/slocum_comet.toml",
    ("./glider sil", "--legs", "N"): "1",
    ("./glider sil", "--fault", "NAME@TIME"): "leak@150",
    ("./glider sil", "--slocum-dir", "DIR"): "{tmp}/slocum",
    ("./glider sil", "--sbdlist", "FILE"): "boards/sbdlist.dat",
    ("./glider sil", "--max-sim-time-s", "S"): "7200",
    ("./glider regress", None, "DIR"): "tests/cards/abort_leak.toml",
    ("./glider regress", None, "DIR|CARD"): "tests/cards/abort_leak.toml",
    ("./glider campaign run", None, "FILE"): "tests/campaign/demo_small.toml",
    ("./glider campaign run", "--shards", "N"): "2",
    ("./glider campaign run", "--first", "N"): "2",
    ("./glider campaign status", None, "DIR"): "{campaign}",
    ("./glider campaign report", None, "DIR"): "{campaign}",
    (None, "--jobs", "N"): "2",
    ("./glider fleet run", None, "LOG"): "{demo_log}",
    ("./glider fleet run", None, "LOGS_OR_DIRS"): "{demo_log}",
    ("./glider steady", "--vehicle", "FILE"): "boards/vehicles/slocum_we01.toml",
    ("./glider steady", "--ballast-cc", "X"): "-250",
    ("./glider steady", "--battpos-in", "Y"): "0.1",
    ("./glider steady", "--depth-m", "D"): "100",
    ("./glider convert", "--cache", "DIR"): "tests/data/real/dbd/comet-2019/cac",
    ("./glider convert", None, "FILE"): COMET_DBD,
    ("./glider convert", None, "FILES"): COMET_DBD,
    ("./glider diagnose", None, "LOG.csv"): "{demo_log}",
    ("./glider diagnose", None, "FILE"): "{demo_log}",
    ("./glider diagnose", "--cache", "DIR"): "tests/data/real/dbd/comet-2019/cac",
    ("./glider diagnose", "--fit", "IDS"): "drag_change,buoyancy_offset",
    ("./glider diagnose", "--window-m", "A,B"): "10,35",
    ("./glider health", None, "DIR|FILES"): "tests/data/real/dbd/comet-2016",
    ("./glider health", "--state", "FILE"): "{tmp}/state.json",
    ("./glider health", "--hours-apart", "H"): "8",
    ("./glider shore serve", "--root", "DIR"): "{tmp}/shore",
    ("./glider shore serve", "--cache", "DIR"): "tests/data/real/dbd/comet-2019/cac",
    ("./glider shore queue", None, "GLIDER"): "comet",
    ("./glider shore queue", None, "FILE"): "boards/missions/comet-nsb3/missions/nsb3.mi",
    ("./glider shore dialog", None, "FILE"): "tests/shore/data/surface_dialog.txt",
    ("./glider diagnose-deployment", None, "LOG"): "{demo_deployment}",
    ("./glider diagnose-deployment", None, "LOGS"): "{demo_deployment}",
    ("./glider diagnose-deployment", "--join", "N"): "1",
    ("./glider diagnose-deployment", "--days-apart", "D"): "1",
    ("./glider validate", None, "DIR"): "{tmp}/validation",
    ("./glider benchmark diagnose", "--draws", "N"): "1",
    ("./glider benchmark diagnose", "--jobs", "J"): "1",
    ("./glider benchmark diagnose", "--seed", "S"): "1",
    ("./glider benchmark diagnose", "--cases", "A,B+C"): "buoyancy_offset",
    ("./glider convert", None, "DIR"): "tests/data/real/dbd/comet-2019",
    ("./glider convert", "--metadata", "deployment.toml"): "tests/netcdf/data/comet.toml",
    ("./glider convert", "--vehicle", "VEHICLE.toml"): "boards/vehicles/slocum_shallow.toml",
    ("./glider shore queue", None, "GLIDER"): "comet",
    ("./glider check-nc", None, "FILE.nc"): "{og1_file}",
    ("./glider shore queue", None, "goto_l10.ma"): "boards/missions/comet-nsb3/mafiles/goto_l10.ma",
    ("./glider actuator-sim", "--tcp", "HOST:PORT"): "127.0.0.1:0",
    ("./glider actuator-sim", "--board", "FILE"): "boards/actuators/default_modbus.toml",
    ("./glider actuator-sim", "--fault", "KIND:VALUE"): "stall:5",
    ("./glider bench", "--tcp", "HOST:PORT"): "{actuator_sim}",
    ("./glider bench", "--board", "FILE"): "boards/actuators/default_modbus.toml",
    ("./glider bench", "--csv", "FILE"): "{tmp}/bench.csv",
    ("./glider bench", None, "SUBCOMMAND"): "status",
    ("./glider plant", "--dir", "DIR"): "{tmp}/hil",
    ("./glider plant", "--vehicle", "FILE"): "boards/vehicles/slocum_we01.toml",
    ("./glider plant", "--fault", "NAME@TIME"): "pump_stall@60",
    ("./glider plant", "--seed", "N"): "1",
    ("./glider plant", "--truth", "FILE.csv"): "{tmp}/hil/truth.csv",
    (None, "--time-scale", "X"): "10",
    ("./glider dead-bus", None, "CYCLES"): "3",
    (None, "--vehicle", "FILE"): "boards/vehicles/slocum_comet.toml",
    (None, "--env", "FILE"): "boards/environments/steady_current.toml",
    (None, "--env", "ENV"): "boards/environments/steady_current.toml",
    (None, "--out", "LOG.csv"): "{tmp}/log.csv",
    (None, "--out", "DIR"): "{tmp}/out",
    (None, "--out", "FILE.nc"): "{tmp}/out.nc",
    (None, "--report", "DIR"): "{tmp}/report",
    (None, "--junit", "FILE"): "{tmp}/junit.xml",
    (None, "--columns", "a,b,..."): "m_depth,m_pitch,m_ballast_pumped",
}


def code_lines(path):
    """(line number, text, skip reason or None, in_block, block language) of every line."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    out = []
    block = None  # language of the open fenced block
    block_skip = None
    pending_skip = None
    indented_start = None  # first line of the open indented code block
    for number, line in enumerate(lines, 1):
        fence = re.match(r"^\s*```(\S*)", line)
        skip = SKIP.search(line)
        # An indented code block (four spaces, after a blank line, outside a fence) is a code block too: its
        # command lines are commands as in a fenced sh block.
        if block is None and not fence:
            previous = lines[number - 2] if number >= 2 else ""
            if line.startswith("    ") and line.strip() and (indented_start is not None or not previous.strip()):
                if indented_start is None:
                    # A mark for the block: on the line before its blank line (an HTML comment cannot touch it).
                    mark = SKIP.search(lines[number - 3]) if number >= 3 else None
                    indented_start, indented_skip = number, mark.group(1) if mark else None
                out.append((number, line, indented_skip, "sh", indented_start))
                continue
            if line.strip():
                indented_start = None
        if fence:
            if block is None:
                block, block_skip = fence.group(1), pending_skip
                block_start = number
            else:
                block, block_skip = None, None
            pending_skip = None
            continue
        if block is None:
            pending_skip = skip.group(1) if skip and line.strip().startswith("<!--") else None
        out.append((number, line, block_skip if block is not None else (skip.group(1) if skip else None), block,
                    block_start if block is not None else None))
    return out


def extract(path):
    """The commands of one markdown file: (line, text, skip reason, kind) with kind block or span."""
    commands = []
    lines = code_lines(path)
    i = 0
    while i < len(lines):
        number, line, skip, block, block_start = lines[i]
        i += 1
        if block is not None:
            if block not in ("", "sh", "bash", "shell", "console"):
                continue
            text = line.strip()
            prompted = text.startswith("$ ")
            if prompted:
                text = text[2:]
            elif block == "" or block == "console":
                continue  # an untagged block: only prompted lines are commands, the rest is output
            if not re.match(PROGRAM + r"(\s|$)", text) and not text.startswith("/usr/bin/time "):
                continue
            while text.endswith("\\") and i < len(lines):
                text = text[:-1] + " " + lines[i][1].strip()
                i += 1
            text = re.sub(r"\s+#.*$", "", text)  # a trailing comment
            # A transcript whose first output line is the program's error ("glider-bench: refused: ...")
            # documents a refusal: the command must fail (exit 1), not succeed.
            following = lines[i][1].strip() if i < len(lines) and lines[i][3] is not None else ""
            refusal = prompted and re.match(r"glider-[a-z-]+: (?!ready)", following) is not None
            commands.append((number, text.strip(), skip, ("refusal@" if refusal else "block@") + str(block_start)))
        else:
            in_table = line.lstrip().startswith("|")
            for span in re.findall(r"`([^`]+)`", line):
                if re.match(r"\./glider(\s|$)", span):
                    # In the text, `./glider SUB` or `./glider SUB --option` names a command (checked to exist);
                    # with arguments, or in a table of commands, it is a command line (run).
                    words = span.split()
                    reference = not in_table and all(w.startswith("-") or w == "..." for w in words[2:])
                    commands.append((number, span.replace("\\|", "|"), skip, "reference" if reference else "span"))
                elif re.match(r"glider-[a-z-]+\s+-", span):
                    commands.append((number, span.replace("\\|", "|"), skip, "options"))
    return commands


def tokens(text):
    # Brackets and parentheses are the synopsis' own, except inside quotes (a glob: 'logs/*.[de]bd').
    parts = re.split(r"""('[^']*'|"[^"]*")""", text)
    text = "".join(part if part[:1] in ("'", '"') else re.sub(r"([\[\]()])", r" \1 ", part) for part in parts)
    return shlex.split(text.replace("] ...", "]"))


def first_alternative(items):
    """Items up to the first top-level `|`; groups expanded: [..] included, (..) first alternative."""
    out, depth, current = [], 0, []
    for item in items:
        if item in ("[", "("):
            depth += 1
        elif item in ("]", ")"):
            depth -= 1
        if item == "|" and depth == 0:
            break
        current.append(item)
    return current


def expand(items):
    """Flattens a synopsis: optional groups included, alternatives' first taken."""
    out = []
    i = 0
    while i < len(items):
        item = items[i]
        if item in ("[", "("):
            depth, j = 1, i + 1
            while depth:
                depth += items[j] in ("[", "(")
                depth -= items[j] in ("]", ")")
                j += 1
            out += expand(first_alternative(items[i + 1:j - 1]))
            i = j
            continue
        if item == "...":
            i += 1
            continue
        if item.endswith("...") and item != "a,b,...":
            item = item[:-3]
        out.append(item)
        i += 1
    return out


def command_key(words):
    if words[0] != "./glider":
        return os.path.basename(words[0])
    key = "./glider " + words[1] if len(words) > 1 else "./glider"
    if len(words) > 2 and words[1] in ("campaign", "fleet", "shore", "benchmark"):
        key += " " + words[2].split("|")[0]
    return key


def top_level(items):
    """The synopsis' top level: ("group", tokens with brackets) or ("word", token)."""
    out, i = [], 0
    while i < len(items):
        if items[i] in ("[", "("):
            depth, j = 1, i + 1
            while depth:
                depth += items[j] in ("[", "(")
                depth -= items[j] in ("]", ")")
                j += 1
            out.append(("group" if items[i] == "[" else "choice", items[i:j]))
            i = j
        else:
            out.append(("word", [items[i]]))
            i += 1
    return out


def variants(text):
    """The synopsis with every optional part, and for each optional group that comes before a positional
    argument, the synopsis without the optional groups between the two: `[--cache DIR] [--columns ...]
    FILE...` is also run as `--cache DIR FILE...` (a multi-value option must not swallow the files)."""
    try:
        items = top_level(tokens(text))
    except (ValueError, IndexError):
        return [text]
    out = [text]
    for g, (kind, _) in enumerate(items):
        if kind != "group":
            continue
        for p in range(g + 1, len(items)):
            word = items[p][1][0]
            previous = items[p - 1]
            if items[p][0] == "word" and not word.startswith("-") and word != "..." and \
                    not (previous[0] == "word" and previous[1][0].startswith("-")):
                dropped = [i for i in range(g + 1, p) if items[i][0] == "group"]
                if dropped:
                    kept = [item for i, item in enumerate(items) if i not in dropped]
                    variant = " ".join(" ".join(tokens_) for _, tokens_ in kept)
                    if variant not in out:
                        out.append(variant)
                break
    return out


def instantiate(text, tmp):
    """The synopsis as a runnable argv, or raises KeyError naming a placeholder without a small input."""
    words = expand(tokens(text))
    key = command_key(words)
    argv, previous = [], None
    for word in words:
        value = word
        first = word.split("|")[0].removesuffix("...")
        literal = (key, previous, word) in PLACEHOLDERS or (key, None, word) in PLACEHOLDERS
        if not word.startswith("-") and " " not in word and (PLACEHOLDER.search(word) or word == "a,b,..." or literal):
            # After a flag (--yes) a positional looks like an option's value: the positional entry is the fallback.
            for candidate in ((key, previous, word), (key, previous, first), (None, previous, word),
                              (None, previous, first), (key, None, word), (key, None, first)):
                if candidate in PLACEHOLDERS:
                    value = PLACEHOLDERS[candidate]
                    break
            else:
                if "|" in word and not PLACEHOLDER.search(word.split("|")[0]):
                    value = word.split("|")[0]  # a choice of literal words: the first
                else:
                    raise KeyError(f"{word} (after {previous or 'the command'}, in {key})")
        elif "|" in word:
            value = word.split("|")[0]
        if value == "{demo_deployment}":
            argv += demo_deployment()
            previous = None
            continue
        if "{demo_log}" in value:
            value = value.replace("{demo_log}", demo_log())
        if "{campaign}" in value:
            value = value.replace("{campaign}", small_campaign(tmp))
        if "{og1_file}" in value:
            value = value.replace("{og1_file}", og1_file(tmp))
        if "{actuator_sim}" in value:
            value = value.replace("{actuator_sim}", actuator_sim(tmp))
        argv.append(value.format(tmp=tmp))
        previous = word if word.startswith("-") else None
    return argv


SMALL_CAMPAIGN = {}
DEMO = {}


def demo_log():
    """The demo mission's SIL log (1342 rows, ~0.1 s to fly): a small log for diagnose."""
    if "log" not in DEMO:
        DEMO["dir"] = tempfile.mkdtemp(prefix="doc_cmd_demo_")
        DEMO["log"] = os.path.join(DEMO["dir"], "demo_flight.csv")
        sil = program_path(SMALL_CAMPAIGN["build"], "glider-sil")
        subprocess.run([sil, "--quiet", "--mission", "boards/missions/demo_yo.toml", "--out", DEMO["log"]],
                       cwd=SMALL_CAMPAIGN["source"], capture_output=True, timeout=60, check=True)
    return DEMO["log"]


def og1_file(tmp):
    """An OG1.0 file glider-convert writes of one real segment (tests/netcdf's metadata): for check-nc."""
    out = os.path.join(tmp, "comet-2019-154.og1.nc")
    convert = program_path(SMALL_CAMPAIGN["build"], "glider-convert")
    subprocess.run([convert, "--format", "og1", "--metadata", "tests/netcdf/data/comet.toml", COMET_DBD,
                    "--out", out], cwd=SMALL_CAMPAIGN["source"], capture_output=True, timeout=60, check=True)
    return out


def demo_deployment():
    """Three segments for diagnose-deployment: the demo log a day apart each, its times made a clock's
    (seconds since 1970) as a glider's own logs have them."""
    with open(demo_log(), encoding="utf-8") as f:
        lines = f.read().split("\n")
    logs = []
    for day in range(3):
        path = os.path.join(os.path.dirname(demo_log()), f"segment-{day}.csv")
        out, column = [], None
        for line in lines:
            if line.startswith("#") or not line:
                out.append(line)
            elif column is None:
                column = line.split(",").index("m_present_time")
                out.append(line)
            else:
                fields = line.split(",")
                fields[column] = repr(float(fields[column]) + 1.7e9 + day * 86400.0)
                out.append(",".join(fields))
        with open(path, "w", encoding="utf-8") as f:
            f.write("\n".join(out))
        logs.append(path)
    return logs


def small_campaign(tmp):
    """A small campaign's results directory (tests/campaign/demo_small.toml, ~1 s) for status and report."""
    if "dir" not in SMALL_CAMPAIGN:
        SMALL_CAMPAIGN["dir"] = tempfile.mkdtemp(prefix="doc_cmd_campaign_")
        status, output, _ = run(["./glider", "campaign", "run", "tests/campaign/demo_small.toml", "--out",
                                 SMALL_CAMPAIGN["dir"]], SMALL_CAMPAIGN["source"], SMALL_CAMPAIGN["build"])
        if status != 0:
            raise KeyError("{campaign}: the small campaign did not run: " + output[-300:])
    return SMALL_CAMPAIGN["dir"]


def start_server(argv, source_dir, build_dir, log_path):
    """Starts a server command; returns (process, None) once it has printed its first line, or (None, why)."""
    env = dict(os.environ, GLIDER_NO_BUILD="1", GLIDER_BUILD_DIR=build_dir, HOME=source_dir)
    log = open(log_path, "w+", encoding="utf-8")
    proc = subprocess.Popen(["bash", "./glider"] + argv[1:], cwd=source_dir, env=env, stdout=log,
                            stderr=subprocess.STDOUT, start_new_session=True)
    deadline = time.monotonic() + 10
    while time.monotonic() < deadline:
        if proc.poll() is not None:
            log.seek(0)
            return None, f"exited {proc.returncode}: {log.read()[-400:]}"
        log.seek(0)
        if log.read().strip():
            time.sleep(SERVER_CHECK_S)
            if proc.poll() is None:
                return proc, None
        time.sleep(0.05)
    stop_server(proc)
    return None, "printed nothing in 10 s"


def stop_server(proc):
    if proc is not None and proc.poll() is None:
        os.killpg(proc.pid, 15)
        try:
            proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, 9)
            proc.wait(timeout=10)


ACTUATOR_SIM = {}


def actuator_sim(tmp):
    """HOST:PORT of a background actuator simulator (port chosen by it) for a bench synopsis."""
    if "address" not in ACTUATOR_SIM:
        log_path = os.path.join(tempfile.mkdtemp(prefix="doc_cmd_sim_"), "sim.log")
        proc, why = start_server(["./glider", "actuator-sim", "--tcp", "127.0.0.1:0"], SMALL_CAMPAIGN["source"],
                                 SMALL_CAMPAIGN["build"], log_path)
        if proc is None:
            raise KeyError("{actuator_sim}: the simulator did not start: " + why)
        with open(log_path, encoding="utf-8") as f:
            found = re.search(r"serving tcp (\S+:\d+)", f.read())
        if not found:
            stop_server(proc)
            raise KeyError("{actuator_sim}: no 'serving tcp HOST:PORT' line")
        ACTUATOR_SIM.update(proc=proc, address=found.group(1), dir=os.path.dirname(log_path))
    return ACTUATOR_SIM["address"]


def program_path(build_dir, name):
    for root, _, files in os.walk(build_dir):
        if name in files and "CMakeFiles" not in root and os.access(os.path.join(root, name), os.X_OK):
            return os.path.join(root, name)
    return None


def run(argv, source_dir, build_dir):
    env = dict(os.environ, GLIDER_NO_BUILD="1", GLIDER_BUILD_DIR=build_dir, GLIDER_SKIP_CROSS="1", HOME=source_dir)
    # As the shell would: a word with * or ? is the files it matches (docs/netcdf.md's profiles/*.nc).
    argv = [a for word in argv for a in (sorted(glob.glob(word, root_dir=source_dir)) or [word]
                                         if re.search(r"[*?]", word) and not word.startswith("-") else [word])]
    if argv[0].startswith("build/release/"):
        argv = [os.path.join(build_dir, argv[0][len("build/release/"):])] + argv[1:]
    elif argv[0].startswith("glider-"):
        argv = [program_path(build_dir, argv[0]) or argv[0]] + argv[1:]
    elif argv[0] == "./glider":
        argv = ["bash", "./glider"] + argv[1:]
    start = time.monotonic()
    try:
        proc = subprocess.run(argv, cwd=source_dir, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                              text=True, timeout=TIMEOUT_S, check=False)
    except subprocess.TimeoutExpired:
        return None, f"no end in {TIMEOUT_S} s", time.monotonic() - start
    return proc.returncode, proc.stdout, time.monotonic() - start


def check_options(text, source_dir, build_dir, helps):
    """Options named in a `glider-x --opt ...` span exist in glider-x --help."""
    words = tokens(text)
    name = words[0]
    if name not in helps:
        path = program_path(build_dir, name)
        if path is None:
            return f"{name}: no such program in the build"
        proc = subprocess.run([path, "--help"], capture_output=True, text=True, timeout=30, check=False)
        helps[name] = proc.stdout + proc.stderr
    unknown = [w for w in words[1:] if re.match(r"--[a-z]", w) and not re.search(re.escape(w) + r"\b", helps[name])]
    return f"{name} has no option {', '.join(unknown)}" if unknown else None


def main(argv):
    if len(argv) not in (3, 4):
        print(__doc__.strip().splitlines()[-1].strip(), file=sys.stderr)
        return 2
    source_dir, build_dir = os.path.abspath(argv[0]), os.path.abspath(argv[1])
    listing = len(argv) == 4 and argv[3] == "--list"
    docs = [argv[2]]
    all_docs = ["README.md"] + sorted("docs/" + f for f in os.listdir(os.path.join(source_dir, "docs"))
                                      if f.endswith(".md"))
    marked = {}  # command -> why it is skipped, from every doc's marks
    for doc in all_docs:
        for _, text, skip, _ in extract(os.path.join(source_dir, doc)):
            if skip:
                only = re.match(r"`([^`]+)`\s*(.*)", skip)
                if not only or text.startswith(only.group(1)):
                    marked.setdefault(text, only.group(2) if only else skip)
    scratch = tempfile.mkdtemp(prefix="doc_cmd_tree_")
    for entry in os.listdir(source_dir):
        if entry not in ("build", ".git"):
            os.symlink(os.path.join(source_dir, entry), os.path.join(scratch, entry))
    source_dir = scratch
    SMALL_CAMPAIGN.update(source=source_dir, build=build_dir)
    subcommands = set(re.findall(r"(?m)^  ([a-z][a-z-]+)", subprocess.run(
        ["bash", "./glider", "help"], cwd=source_dir, capture_output=True, text=True, timeout=30).stdout))
    failures, skipped, ran, checked, seen = [], [], 0, 0, set()
    helps = {}
    session = None  # a server serving the rest of a transcript block
    for doc in docs:
        for number, text, skip, kind in extract(os.path.join(source_dir, doc)):
            where = f"{doc}:{number}"
            if session is not None and session[0] != (doc, kind.split("@")[-1]):
                stop_server(session[1])
                session = None
            if kind == "reference":
                checked += 1
                words = text.split()
                if len(words) > 1 and words[1] not in subcommands:
                    failures.append(f"{where}: `{text}`: ./glider has no command {words[1]} (./glider help)")
                continue
            if kind == "options":
                checked += 1
                problem = check_options(text, source_dir, build_dir, helps)
                if problem:
                    failures.append(f"{where}: `{text}`: {problem}")
                continue
            if text in marked:
                skipped.append(f"{where}: {text}  -- {marked[text]}")
                continue
            if text in seen and not kind.startswith("refusal@"):
                continue
            seen.add(text)
            for variant in variants(text):
                with tempfile.TemporaryDirectory(prefix="doc_cmd_") as tmp:
                    try:
                        command = instantiate(variant, tmp)
                    except KeyError as error:
                        failures.append(f"{where}: `{text}`: no small input for the placeholder {error.args[0]}: add one "
                                        f"to PLACEHOLDERS in tests/docs/check_doc_commands.py or mark the line "
                                        f"<!-- doc-test: skip REASON -->")
                        continue
                    if listing:
                        print(f"{where}: {shlex.join(command)}")
                        continue
                    ran += 1
                    if command_key(command) in SERVERS:
                        start = time.monotonic()
                        proc, why = start_server(command, source_dir, build_dir, os.path.join(tmp, "server.log"))
                        ok = proc is not None
                        print(f"{'ok  ' if ok else 'FAIL'} {where} (server, {time.monotonic() - start:.1f} s): "
                              f"{shlex.join(command)}")
                        if not ok:
                            failures.append(f"{where}: `{text}`: the server {why}")
                        elif kind.startswith("block@"):
                            session = ((doc, kind.split("@")[-1]), proc)  # serves the block's next commands
                        else:
                            stop_server(proc)
                        continue
                    status, output, seconds = run(command, source_dir, build_dir)
                    if kind.startswith("refusal@"):
                        ok = status not in (0, None)
                    elif re.search(r"\b(sil|glider-sil|glider-firmware)\b", text):
                        ok = status in (0, 3)
                    else:
                        ok = status == 0
                    print(f"{'ok  ' if ok else 'FAIL'} {where} ({seconds:.1f} s, exit {status}): {shlex.join(command)}")
                    if not ok:
                        tail = "\n".join(output.strip().splitlines()[-6:]) if output else ""
                        failures.append(f"{where}: `{text}` -> exit {status}:\n      " + tail.replace("\n", "\n      "))
    if session is not None:
        stop_server(session[1])
    stop_server(ACTUATOR_SIM.get("proc"))
    for directory in (SMALL_CAMPAIGN.get("dir"), DEMO.get("dir"), ACTUATOR_SIM.get("dir"), scratch):
        if directory:
            shutil.rmtree(directory, ignore_errors=True)
    print(f"\n{ran} documented commands run, {checked} command and option references checked, {len(skipped)} skipped by "
          f"the docs' own marks:")
    for line in skipped:
        print("  skip " + line)
    for failure in failures:
        print("FAIL: " + failure)
    print("FAIL doc_commands" if failures else "PASS doc_commands")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
