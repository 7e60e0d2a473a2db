"""The one exception the viewer's commands turn into a one-line message and exit code 2."""


class ViewerError(Exception):
    """A problem the user can fix (bad option, missing log, port in use): one line, exit 2."""


def one_line(exc: BaseException) -> str:
    return " ".join(str(exc).split()) or type(exc).__name__
