"""Probe 50's oracle (tests/slow/probe_stop50/oracle.py), loaded from there: one copy for both
probes. Importable here as `oracle`, as this probe's scripts expect."""
import importlib.util, os

_path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "probe_stop50", "oracle.py")
_spec = importlib.util.spec_from_file_location("probe_stop50_oracle", _path)
_module = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_module)
globals().update({k: v for k, v in vars(_module).items() if not k.startswith("__")})
