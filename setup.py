"""pip install . (the repository root) builds the Python package as pip install ./python does."""
import pathlib
import runpy

runpy.run_path(str(pathlib.Path(__file__).resolve().parent / "python" / "setup.py"))
