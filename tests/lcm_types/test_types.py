"""The LCM types: conventions of every .lcm file, and the Java jar that lcm-spy uses."""
import os
import re
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
TYPES = sorted((ROOT / "lcm_types").glob("*.lcm"))
JAR = Path(os.environ.get("TOUCHLINE_BUILD_DIR", ROOT / "build")) / "lcm_types" / "touchline-types.jar"
FIELD = re.compile(r"^\s*(?!const|package)([\w.]+)\s+(\w+)(\[[^\]]*\])?\s*;(.*)$")


def fields(path: Path) -> list:
    return [FIELD.match(line) for line in path.read_text().splitlines() if FIELD.match(line)]


def is_value_type(path: Path) -> bool:
    return "Value type" in path.read_text()


def test_there_are_types():
    assert len(TYPES) >= 5


@pytest.mark.parametrize("path", TYPES, ids=lambda p: p.name)
def test_one_type_per_file_named_after_it(path):
    structs = re.findall(r"^struct\s+(\w+)", path.read_text(), re.M)
    assert structs == [path.stem]


@pytest.mark.parametrize("path", TYPES, ids=lambda p: p.name)
def test_messages_start_with_utime_and_every_field_is_documented(path):
    found = fields(path)
    if not is_value_type(path):
        assert found[0].group(1) == "int64_t" and found[0].group(2) == "utime", "utime must come first"
    for m in found:
        assert "//" in m.group(4), f"{path.name}: field {m.group(2)} has no comment (units)"


def test_java_jar_decodes_every_message_type(tmp_path):
    import touchline

    messages = [p.stem for p in TYPES if not is_value_type(p)]
    for i, name in enumerate(messages):
        msg = getattr(touchline, name)()
        msg.utime = 1000 + i
        for field in fields(ROOT / "lcm_types" / f"{name}.lcm"):
            if field.group(1) == "byte" and field.group(3):
                # lcm-gen 1.3.1's Python defaults byte arrays to "" (a str), which Python 3
                # cannot encode: bytes it must be.
                setattr(msg, field.group(2), b"")
        (tmp_path / f"{name}.bin").write_bytes(msg.encode())
    result = subprocess.run(["java", "-cp", f"/usr/share/java/lcm.jar:{JAR}",
                             str(Path(__file__).with_name("DecodeCheck.java")), str(tmp_path)],
                            capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stderr
    decoded = dict(line.split(" utime=") for line in result.stdout.strip().splitlines())
    assert decoded == {n: str(1000 + i) for i, n in enumerate(messages)}
