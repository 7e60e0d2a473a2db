"""LogIndex: one pass over a log that keeps where each truth, sense and act is (not what it says),
the raw game, status and event messages and the first TL_MATCH; the offsets it keeps read back
the very messages the log holds, and a truncated tail keeps what came before."""
import lcm
import pytest

from known_log import COVARIANCES, FRAMES, SENSE_FRAMES, known_messages, utime_of, write_known_log
from touchline_viewer.log_index import LogIndex


@pytest.fixture(scope="module")
def index(known_log):
    index = LogIndex(known_log)
    yield index
    index.close()


def logged(channel: str) -> list:
    return [m.encode() for _, c, m in known_messages() if c == channel]


def test_every_truth_is_indexed_by_time_and_frame(index):
    assert list(index.truth_utimes) == [utime_of(k) for k in range(FRAMES)]
    assert list(index.truth_frames) == list(range(FRAMES))
    assert [index.truth_bytes(k) for k in range(FRAMES)] == logged("TL_TRUTH"), "the offsets read the messages back"
    assert not index.truncated


def test_senses_are_indexed_by_the_frame_they_belong_to(index):
    assert sorted(index.sense_at) == list(SENSE_FRAMES)
    assert [index.bytes_at(*index.sense_at[k]) for k in SENSE_FRAMES] == logged("TL_SENSE")


def test_acts_are_indexed_per_robot_by_frame(index):
    assert sorted(index.acts) == sorted(COVARIANCES)
    for (team, player), (frames, at) in index.acts.items():
        assert list(frames) == list(range(FRAMES))
        assert [index.bytes_at(at[2 * k], at[2 * k + 1]) for k in range(FRAMES)] == logged(f"TL_ACT_{team}_{player}")


def test_small_channels_are_kept_raw_and_the_first_match_only(index):
    for channel in ("TL_GAME", "TL_STATUS", "TL_EVENT"):
        assert index.raw[channel] == logged(channel)
    assert index.first_match == logged("TL_MATCH")[0]


def test_a_truncated_tail_keeps_what_came_before(tmp_path, known_log):
    cut = tmp_path / "cut.lcmlog"
    data = known_log.read_bytes()
    cut.write_bytes(data[:len(data) - 40])  # the last event (a TL_TRUTH) loses its end
    index = LogIndex(cut)
    try:
        assert index.truncated
        assert list(index.truth_frames) == list(range(FRAMES - 1))
    finally:
        index.close()


def test_other_channels_and_short_messages_are_skipped(tmp_path):
    path = tmp_path / "odd.lcmlog"
    log = lcm.EventLog(str(path), "w", overwrite=True)
    log.write_event(0, "TL_TRUTH", b"\x00" * 10)  # too short to hold a time and a frame
    log.write_event(0, "TL_ACT_X", b"\x00" * 60)  # not TL_ACT_<team>_<player>
    log.write_event(0, "SOMETHING", b"\x00" * 60)
    log.close()
    index = LogIndex(path)
    try:
        assert (len(index.truth_frames), index.acts, index.sense_at) == (0, {}, {})
    finally:
        index.close()


def test_the_index_opens_a_log_it_did_not_write(tmp_path):
    """A log as lcm-logger writes it, events numbered and timed by the wall clock, indexes the same."""
    path = write_known_log(tmp_path / "again.lcmlog")
    index = LogIndex(path)
    try:
        assert len(index.truth_frames) == FRAMES
    finally:
        index.close()
