"""Schemathesis hooks for figment-serve's contract test (tests/serve/scenarios/test_contract.py).

Each parameter's schema in serve/http/openapi.json says what the server takes for it whatever
the other parameters are: the union over a request without `sex` (the Mannequin) and one
with each sex. The rules between parameters, which OpenAPI 3 cannot state, are in the
parameters' descriptions and, where they are data, in the document's own extensions
(`x-figment-by-sex`: each sex's range, enumeration or pattern; `x-figment-max-pixels`),
which test_serve checks against the server's constants. A case Schemathesis generates as
valid (positive) that breaks such a rule is refused with the 400 the description
announces, so before it is sent it is made to keep the rules, and only positive cases are:

  - a number outside its sex's range (but within another case's) is brought to the
    nearest end of it;
  - an optional parameter whose value its sex does not take but another case does (a
    Mannequin's pose with a sex, a chart size without one, fitmap=ease without a sex) is
    left out: the default then applies;
  - a value no case takes is sent as generated: the server must refuse it, and then the
    schema that allowed it is wrong;
  - chest given beside bust with another text is left out (bust and chest must agree);
  - an outfit that wears a style twice is left out;
  - a posed measured body keeps its pose only in one garment, sitting only in a tshirt or
    nothing (the default outfit, a dress, counts), else the pose is left out;
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


def _kept(rule, value):
    """`value` as its sex's rule takes it (a number brought into the range), or None to leave it out."""
    if "minimum" in rule:
        return min(max(_number(value), rule["minimum"]), rule["maximum"])
    return value if _takes(rule, value) else None


def _by_sex(values, parameters):
    sex = _text(values.get("sex", "none"))
    for name, parameter in parameters.items():
        rules = parameter.get("x-figment-by-sex", {})
        if sex not in rules or name not in values:
            continue
        # A value no case takes is sent as it is: the schema should not have allowed it, and
        # the server's refusal is the finding (a loosened document, say).
        if any(_takes(rule, values[name]) for rule in rules.values()):
            values[name] = _kept(rules[sex], values[name])


def _outfit(values):
    outfit = values.get("outfit")
    if outfit is None:
        return ["dress"]  # the default outfit
    items = [item.split(":")[0] for item in _text(outfit).split(",") if item and _text(outfit) != "none"]
    if len(items) != len(set(items)):
        values["outfit"] = None
        return ["dress"]
    return items


def _between(values, parameters):
    if values.get("bust") is not None and values.get("chest") is not None and \
            _text(values["bust"]) != _text(values["chest"]):
        values["chest"] = None
    styles = _outfit(values)
    pose = values.get("pose")
    if values.get("sex") is not None and pose is not None and _text(pose) != "rest":
        if len(styles) > 1 or (_text(pose) == "sitting" and styles and styles != ["tshirt"]):
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
    _by_sex(values, parameters)
    _between(values, parameters)
    case.query = {name: values[name] for name in query if values[name] is not None}
    if isinstance(case.body, dict):
        case.body = {name: values[name] for name in form if values[name] is not None}
    return case
