"""Touchline's tools/ folder as `pip install .` installs it (cmake/install.cmake): the launcher,
sweeps, the text spy and their modules, run by the console scripts (console_scripts.py)."""
