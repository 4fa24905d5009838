"""Schemathesis hooks for figment-serve's contract test (tests/serve/scenarios/test_contract.py).

Each parameter's schema in serve/http/openapi.json says what the server takes for it whatever
the other parameters are: the union over the Mannequin (body=mannequin) and a made body of
each sex (the default, women's unless `sex` says). The rules between parameters, which
OpenAPI 3 cannot state, are in the parameters' descriptions and, where they are data, in the
document's own extensions (`x-figment-by-body`: each body's range, enumeration or pattern
for a render; `x-figment-by-sex` for a fit; `x-figment-max-pixels`),
which test_serve checks against the server's constants. A case Schemathesis generates as
valid (positive) that breaks such a rule is refused with the 400 the description
announces, so before it is sent it is made to keep the rules, and only positive cases are:

  - a number outside its body's range (but within another case's) is brought to the
    nearest end of it;
  - an optional parameter whose value its body does not take but another case does (a
    Mannequin's pose on a made body, a chart size on the Mannequin, fitmap=ease on the
    Mannequin, a style not sold to the sex) is left out: the default then applies; a
    required one (a fit's style) takes the first value its sex does;
  - sex beside body=mannequin is left out (the Mannequin has none);
  - a value no case takes is sent as generated: the server must refuse it, and then the
    schema that allowed it is wrong;
  - chest given beside bust with another text is left out (bust and chest must agree);
  - an outfit that wears a style twice is left out;
  - a posed made body keeps its pose only in one garment of a cut style (the outfit
    parameter's `x-figment-sewn-styles` are sewn standing), sitting only in a tshirt or
    nothing (the default outfit counts: a dress for women, a tshirt for men), else the pose
    is left out;
  - a size past the pixels in all is left out;
  - POST /api/render: a parameter in both the query and the form is left out of the form.

Negative cases are sent as generated: whatever a schema refuses, the server must refuse.
"""
import re

import schemathesis

RENDER = ("/api/render", "/api/fit")


def _parameters(case):
    """The operation's parameters, by name, as the document writes them (its $refs resolved)."""
    document = case.operation.schema.raw_schema
    operation = document["paths"][case.operation.path][case.operation.method.lower()]
    named = {}
    for parameter in operation.get("parameters", []):
        if "$ref" in parameter:
            parameter = document["components"]["parameters"][parameter["$ref"].rsplit("/", 1)[1]]
        named[parameter["name"]] = parameter
    return named


def _text(value):
    return value if isinstance(value, str) else repr(value) if isinstance(value, float) else str(value)


def _number(value):
    try:
        return float(value)
    except (TypeError, ValueError):
        return None


def _takes(rule, value):
    number = _number(value)
    if "minimum" in rule:
        return number is not None and rule["minimum"] <= number <= rule["maximum"]
    if "enum" in rule:
        return _text(value) in rule["enum"]
    return "pattern" not in rule or re.search(rule["pattern"], _text(value)) is not None


def _kept(rule, value, required):
    """`value` as its body's rule takes it (a number brought into the range), or None to
    leave it out; a required one not taken becomes the rule's first value."""
    if "minimum" in rule:
        return min(max(_number(value), rule["minimum"]), rule["maximum"])
    if _takes(rule, value):
        return value
    return rule["enum"][0] if required and "enum" in rule else None


def _condition(values, extension):
    """The case a request is: its body for a render, its sex for a fit."""
    if extension == "x-figment-by-sex":
        return _text(values.get("sex"))
    if _text(values.get("body")) == "mannequin":
        values["sex"] = None
        return "mannequin"
    return _text(values.get("sex") or "female")


def _by_body(values, parameters):
    for name, parameter in parameters.items():
        extension = "x-figment-by-body" if "x-figment-by-body" in parameter else "x-figment-by-sex"
        rules = parameter.get(extension, {})
        condition = _condition(values, extension)
        if condition not in rules or values.get(name) is None:
            continue
        # A value no case takes is sent as it is: the schema should not have allowed it, and
        # the server's refusal is the finding (a loosened document, say).
        if any(_takes(rule, values[name]) for rule in rules.values()):
            values[name] = _kept(rules[condition], values[name], parameter.get("required", False))


def _outfit(values):
    outfit = values.get("outfit")
    if outfit is None:
        return ["tshirt" if _text(values.get("sex")) == "male" else "dress"]  # the default outfit
    items = [item.split(":")[0] for item in _text(outfit).split(",") if item and _text(outfit) != "none"]
    if len(items) != len(set(items)):
        values["outfit"] = None
        return _outfit(values)
    return items


def _between(values, parameters):
    if values.get("bust") is not None and values.get("chest") is not None and \
            _text(values["bust"]) != _text(values["chest"]):
        values["chest"] = None
    styles = _outfit(values)
    pose = values.get("pose")
    if _text(values.get("body")) != "mannequin" and pose is not None and _text(pose) != "rest":
        sewn = parameters.get("outfit", {}).get("x-figment-sewn-styles", [])
        if len(styles) > 1 or (_text(pose) == "sitting" and styles and styles != ["tshirt"]) or \
                any(style in sewn for style in styles):
            values["pose"] = None
    size = values.get("size")
    if size is not None and "size" in parameters:
        width, height = (int(side) for side in _text(size).split("x"))
        if width * height > parameters["size"]["x-figment-max-pixels"]:
            values["size"] = None


@schemathesis.hook
def map_case(context, case):
    if case.meta is None or not case.meta.generation.mode.is_positive or case.operation.path not in RENDER:
        return case
    parameters = _parameters(case)
    query = dict(case.query or {})
    form = dict(case.body) if isinstance(case.body, dict) else {}
    form = {name: value for name, value in form.items() if name not in query}
    values = dict(query, **form)
    _by_body(values, parameters)
    _between(values, parameters)
    case.query = {name: values[name] for name in query if values[name] is not None}
    if isinstance(case.body, dict):
        case.body = {name: values[name] for name in form if values[name] is not None}
    return case
