"""touchline_paths: where the tree's files are, and which ports a match's LCM URL uses."""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tools"))
from touchline_paths import lane_urls  # noqa: E402


def test_a_match_url_has_the_robots_answers_on_the_port_above():
    """bridge/lcm lanes.cpp's rule (tests/bridge/lcm/test_lanes.cpp has the same cases): the
    robots' answers go to the port above a udpm URL's; any other URL is the only one."""
    assert lane_urls("udpm://239.255.76.67:7667?ttl=0") == ["udpm://239.255.76.67:7667?ttl=0",
                                                           "udpm://239.255.76.67:7668?ttl=0"]
    assert lane_urls("udpm://239.1.2.3:9000") == ["udpm://239.1.2.3:9000", "udpm://239.1.2.3:9001"]
    assert lane_urls("udpm://?ttl=0") == ["udpm://?ttl=0", "udpm://239.255.76.67:7668?ttl=0"]
    assert lane_urls("udpm://239.1.2.3:0x1000") == ["udpm://239.1.2.3:0x1000", "udpm://239.1.2.3:4097"]
    assert lane_urls("udpm://239.1.2.3:65533") == ["udpm://239.1.2.3:65533", "udpm://239.1.2.3:65534"]
    for one in ("memq://", "tcpq://127.0.0.1:7700", "udpm://239.1.2.3:65534", "udpm://239.1.2.3:x"):
        assert lane_urls(one) == [one]
