"""The identity reports of the Demo protocol with every spec feature (spec simulation identity), generated: what a
Device Information reply holds, for the log tools (`logs/identity.py`: the log's model and serial),
the sessions and the simulator (`_sim` re-exports it). A module of its own so that a log command
imports only the reply's set module, not every command module `_sim` needs.

`IDENTITY_REPORTS`: reply class -> ((attribute path, item, string format: (length, pad, justify)
or None for an integer), ...). `IDENTITY`: per device the value of every item (the model name a log's
reply is compared with: `logs/identity.py` `model_matches`).
"""

from __future__ import annotations

from typing import Any, Dict, Tuple

IDENTITY_REPORTS: Dict[Any, Tuple[Tuple[Any, ...], ...]] = {}
IDENTITY: Dict[str, Dict[str, Any]] = {}
