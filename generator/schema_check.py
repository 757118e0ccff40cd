"""JSON Schema checks with located, readable errors (used for spec files and vector files)."""

from __future__ import annotations

import jsonschema

from .diagnostics import SpecError


def deepest(error: jsonschema.ValidationError) -> jsonschema.ValidationError:
    """For oneOf/anyOf failures, the most specific sub-error (the one a person needs to see)."""
    best = error
    while best.context:
        best = jsonschema.exceptions.best_match(best.context)
    return best


def _short(value) -> str:
    """A value as it appears in a message: its repr, cut to a readable length (a hostile file can
    hold a 4 MB string or a 400-digit number)."""
    text = repr(value)
    return text if len(text) <= 60 else text[:40] + f"... ({len(text)} characters)"


def readable_path(data, path) -> str:
    """A path in a spec file as a person reads it: list items that have a name are named
    (`fields[scaled_gyro].role`, not `fields.1.role`)."""
    parts: list[str] = []
    node = data
    for key in path:
        item = None
        try:
            item = node[key]
        except (KeyError, IndexError, TypeError):
            pass
        if isinstance(key, int) and isinstance(item, dict) and isinstance(item.get("name"), str):
            label = item["name"] if len(item["name"]) <= 40 else item["name"][:37] + "..."
            if parts:
                parts[-1] += f"[{label}]"
            else:
                parts.append(f"[{label}]")
        else:
            parts.append(str(key))
        node = item
    return ".".join(parts)


def describe(best: jsonschema.ValidationError, data=None) -> tuple[str, str | None]:
    """Turn a jsonschema error into (what is wrong, what is expected)."""
    where = readable_path(data, best.absolute_path) if data is not None else ".".join(map(str, best.absolute_path))
    where = where or "(top level)"
    v = best.validator
    if v == "required":
        missing = best.message.split("'")[1] if "'" in best.message else best.message
        return f"{where}: missing required key '{missing}'", None
    if v == "additionalProperties":
        return f"{where}: {best.message}", "only the keys documented in docs/spec-format.md"
    if v == "enum":
        return f"{where}: value {_short(best.instance)} is not allowed", "one of " + ", ".join(
            repr(x) for x in best.validator_value
        )
    if v == "pattern":
        return f"{where}: {_short(best.instance)} is not a valid name", f"a name matching {best.validator_value}"
    if v == "type":
        wanted = best.validator_value
        if isinstance(best.instance, bool) and "string" in (wanted if isinstance(wanted, list) else [wanted]):
            return (
                f"{where}: {_short(best.instance)} has the wrong type (YAML reads an unquoted on/off/yes/no as a boolean)",
                "a string: put the word in quotes",
            )
        return f"{where}: {_short(best.instance)} has the wrong type", f"{wanted}"
    if v in ("minimum", "maximum"):
        return f"{where}: {_short(best.instance)} is out of range", f"{v} {best.validator_value}"
    return f"{where}: {best.message}", None


def schema_errors(validator: jsonschema.Validator, data, locate) -> list[SpecError]:
    """Every shape error of `data`, located at its line and column (unknown keys at the key)."""
    errors = []
    for e in sorted(validator.iter_errors(data), key=lambda e: list(map(str, e.absolute_path))):
        best = deepest(e)
        msg, expected = describe(best, data)
        path = tuple(best.absolute_path)
        if best.validator == "additionalProperties" and isinstance(best.instance, dict):
            extra = [k for k in best.instance if k not in best.schema.get("properties", {})]
            if extra:
                path = path + (("key", extra[0]),)
        errors.append(SpecError(locate(path), msg, expected))
    return errors
