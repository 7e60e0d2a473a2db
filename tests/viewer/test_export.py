"""The exporter: a PNG of one moment and a GIF of a span, screenshots of the same page."""
from PIL import Image

from conftest import run_module
from known_log import FRAMES, utime_of

EXPORT = "touchline_viewer.export"


def test_png_of_one_moment_has_the_asked_size(known_log, tmp_path):
    out = tmp_path / "moment.png"
    result = run_module(EXPORT, "--log", known_log, "--at", utime_of(4) / 1e6, "--size", "640x480", "--out", out)
    assert result.returncode == 0, result.stderr
    with Image.open(out) as image:
        assert (image.format, image.size) == ("PNG", (640, 480))
        # the page's own canvas, not a blank page: the carpet's green is there
        assert (0x2E, 0x7D, 0x32) in {rgb for _, rgb in image.convert("RGB").getcolors(1 << 20)}


def test_gif_of_a_span_has_one_frame_per_tick(known_log, tmp_path):
    out = tmp_path / "span.gif"
    start, end, fps = 0.05, 0.35, 20  # 0.3 s at 20 fps: 6 frames, each a different truth frame
    assert end <= utime_of(FRAMES - 1) / 1e6
    result = run_module(EXPORT, "--log", known_log, "--from", start, "--to", end, "--fps", fps,
                        "--size", "480x360", "--out", out)
    assert result.returncode == 0, result.stderr
    assert "6 frames" in result.stdout
    with Image.open(out) as image:
        assert (image.format, image.size, image.n_frames) == ("GIF", (480, 360), 6)
        assert image.info["duration"] == round(1000 / fps)


def test_a_time_outside_the_log_is_one_line_and_exit_2(known_log, tmp_path):
    result = run_module(EXPORT, "--log", known_log, "--at", 99, "--out", tmp_path / "x.png")
    assert result.returncode == 2
    assert result.stderr.count("\n") == 1 and "outside the log" in result.stderr
    assert not (tmp_path / "x.png").exists()
