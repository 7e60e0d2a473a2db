"""One streaming pass over an lcm-logger log that keeps where each message is instead of what
it says: a full match's log (about 110 MB, 10 messages a frame) is indexed in a fraction of a
second, and a frame is decoded only when a page asks for it.

Reads the log's event headers (lcm-logger's format: magic, event number, timestamp, channel and
data lengths, then the channel name and the data) through mmap. Per message it keeps:
- TL_TRUTH: simulated time, frame and where its bytes are (read from the encoding's first
  fields, bytes 8-23 after the type fingerprint, without decoding the rest);
- TL_SENSE: frame and where;
- TL_ACT_<team>_<player>: frame and where, per robot (its belief and team message);
- TL_MATCH (the first), TL_GAME, TL_STATUS, TL_EVENT: the raw bytes (a few thousand messages in
  a full match), decoded by the caller.
Nothing else is read. A truncated or corrupt tail ends the pass: what came before is kept."""
import mmap
import re
import struct
from array import array
from pathlib import Path

LCM_LOG_MAGIC = 0xEDA1DA01  # first bytes of every lcm-logger event, big-endian
_HEADER = struct.Struct(">IqqII")  # magic, event number, timestamp, channel length, data length
_TIME_FRAME = struct.Struct(">qq")  # utime, frame: the first fields after the 8-byte fingerprint
_FRAME = struct.Struct(">q")
_ACT_ID = struct.Struct(">qqbb")  # act_t: utime, frame, team, player
ACT_CHANNEL = re.compile(rb"TL_ACT_(\d+)_(\d+)")

TRUTH, SENSE = b"TL_TRUTH", b"TL_SENSE"
KEPT_RAW = (b"TL_MATCH", b"TL_GAME", b"TL_STATUS", b"TL_EVENT")


class LogIndex:
    """Where every truth, sense and act of a log is. Keep it open while frames are read."""

    def __init__(self, path: Path):
        self.path = Path(path)
        self._file = open(self.path, "rb")
        try:
            self._map = mmap.mmap(self._file.fileno(), 0, access=mmap.ACCESS_READ)
        except ValueError:  # an empty file cannot be mapped
            self._map = b""
        self.truth_utimes = array("q")
        self.truth_frames = array("q")
        self.truth_at = array("q")  # data offset, then length, of each truth: [2i], [2i + 1]
        self.sense_at: dict = {}  # frame -> (offset, length)
        self.acts: dict = {}  # (team, player) -> (frames array, [offset, length, ...] array)
        self.raw: dict = {name.decode(): [] for name in KEPT_RAW}  # channel -> [bytes] in log order
        self.first_match = None
        self.truncated = False  # the pass stopped at bytes that are not an event
        self._scan()

    def close(self) -> None:
        if isinstance(self._map, mmap.mmap):
            self._map.close()
        self._file.close()

    def bytes_at(self, offset: int, length: int) -> bytes:
        return self._map[offset:offset + length]

    def truth_bytes(self, i: int) -> bytes:
        return self.bytes_at(self.truth_at[2 * i], self.truth_at[2 * i + 1])

    def _scan(self) -> None:
        m, end, pos = self._map, len(self._map), 0
        header, time_frame, frame_of, act_id = (_HEADER.unpack_from, _TIME_FRAME.unpack_from,
                                                _FRAME.unpack_from, _ACT_ID.unpack_from)
        utimes, frames, truth_at, sense_at, acts, raw = (self.truth_utimes, self.truth_frames, self.truth_at,
                                                         self.sense_at, self.acts, self.raw)
        while pos + _HEADER.size <= end:
            magic, _, _, channel_len, data_len = header(m, pos)
            data = pos + _HEADER.size + channel_len
            if magic != LCM_LOG_MAGIC or data + data_len > end:
                self.truncated = True
                break
            channel = m[pos + _HEADER.size:data]
            pos = data + data_len
            if data_len < 24:  # too short for any message read here
                continue
            if channel == TRUTH:
                utime, frame = time_frame(m, data + 8)
                utimes.append(utime)
                frames.append(frame)
                truth_at.append(data)
                truth_at.append(data_len)
            elif channel == SENSE:
                sense_at[frame_of(m, data + 16)[0]] = (data, data_len)
            elif channel.startswith(b"TL_ACT_"):
                if data_len < _ACT_ID.size + 8:
                    continue
                _, frame, team, player = act_id(m, data + 8)
                robot = acts.get((team, player))
                if robot is None:
                    if not ACT_CHANNEL.fullmatch(channel):
                        continue
                    robot = acts[(team, player)] = (array("q"), array("q"))
                robot[0].append(frame)
                robot[1].append(data)
                robot[1].append(data_len)
            elif channel in KEPT_RAW:
                if channel == b"TL_MATCH":
                    if self.first_match is None:
                        self.first_match = m[data:pos]
                    continue  # the world repeats it unchanged: the first is the match's
                raw[channel.decode()].append(m[data:pos])
