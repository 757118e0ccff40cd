"""The IR builder's passes, one module each; generator/ir.py runs them in order."""
