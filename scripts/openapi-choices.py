#!/usr/bin/env python3
"""Writes the shop's choices into serve/http/openapi.json: what each body takes for the
render's measurements, pose, outfit and fit map (x-figment-by-body: the Mannequin, a made
woman, a made man), the schemas' unions over them and the fit's styles and ranges
(x-figment-by-sex), from the size chart and the garment catalogue in scenes/.

Run it after changing scenes/sizes/chart.txt or scenes/catalogue/; serve.OpenApiContract
(tests/serve/scenarios/test_OpenApiContract.cpp) checks every value it writes against
the server's parser, so a rule changed in C++ and not here fails there.

    scripts/openapi-choices.py [--check]

--check: exit 1, naming the document, when it is not what this would write.
"""
import json
import os
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir)
DOCUMENT = os.path.join(ROOT, "serve", "http", "openapi.json")
SCENES = os.path.join(ROOT, "scenes")

# serve/request/BodyMeasuresText.cpp: MakeHuman's adults' statures; the chart's girths two
# of its 4 cm steps wider each side.
MADE_STATURE = (1.45, 1.95)
BEYOND_CHART = 0.08
# serve/request/ShopperChoices.cpp: the Mannequin's ranges, its own measurements, its
# styles (the paper's patterns, in no sizes) and poses; serve/request/MeasuredPoses.cpp:
# the made body's rig presets.
MANNEQUIN = {"stature": (1.45, 1.90), "bust": (0.78, 1.10), "waist": (0.60, 0.90), "hips": (0.82, 1.15)}
MANNEQUIN_STYLES = ["dress", "skirt", "tshirt"]
MANNEQUIN_POSES = ["rest", "relaxed", "turn-head"]
MADE_POSES = ["rest", "arms-down", "arm-raised", "walking", "sitting"]
BODIES = ("mannequin", "female", "male")
HEX = "(:[0-9A-Fa-f]{6})?"


def chart():
    """{sex: [(letter, number, stature, bust, waist, hip)]} from scenes/sizes/chart.txt."""
    sizes = {"female": [], "male": []}
    with open(os.path.join(SCENES, "sizes", "chart.txt")) as text:
        for line in text:
            words = line.split("#", 1)[0].split()
            if words:
                sizes[words[0]].append((words[1], words[2]) + tuple(float(w) for w in words[3:7]))
    return sizes


def catalogue():
    """[(style, {sex: [letters]}, sewn)] in the catalogue's order."""
    folder = os.path.join(SCENES, "catalogue")
    styles = []
    with open(os.path.join(folder, "index.txt")) as index:
        for line in index:
            words = line.split("#", 1)[0].split()
            if len(words) == 2 and words[0] == "style":
                name, sizes, sewn = None, {}, False
                with open(os.path.join(folder, words[1])) as style:
                    for entry in style:
                        parts = entry.split("#", 1)[0].split()
                        if parts and parts[0] == "style":
                            name = parts[1]
                        elif parts and parts[0] in ("female", "male"):
                            sizes[parts[0]] = parts[1:]
                        elif parts and parts[0] == "patterns":
                            sewn = True
                styles.append((name, sizes, sewn))
    return styles


def mm(value):
    return round(value * 1000) / 1000


def made_ranges(rows):
    """The made body's accepted ranges, as BodyMeasuresText::ranges."""
    girth = lambda k: (mm(rows[0][k] - BEYOND_CHART), mm(rows[-1][k] + BEYOND_CHART))
    return {"stature": MADE_STATURE, "bust": girth(3), "waist": girth(4), "hips": girth(5)}


def alternatives(words):
    return "(" + "|".join(words) + ")"


def item_pattern(body, sizes, styles):
    """One outfit item a body takes, as a regular expression without anchors."""
    if body == "mannequin":
        return alternatives(MANNEQUIN_STYLES) + HEX
    numbers = {letter: number for letter, number, *_ in sizes[body]}
    items = []
    for name, sold, sewn in styles:
        if not sold.get(body):
            continue
        names = sold[body] + [numbers[letter] for letter in sold[body]]
        items.append(name + ":" + alternatives(names))
    return alternatives(items) + HEX


def outfit_pattern(item):
    return "^(|none|" + item + "(," + item + "){0,2})$"


def by_body(sizes, styles):
    """Each body's rules, by parameter name."""
    rules = {name: {} for name in ("stature", "bust", "chest", "waist", "hips", "pose", "outfit", "fitmap",
                                     "underwear")}
    for body in BODIES:
        ranges = MANNEQUIN if body == "mannequin" else made_ranges(sizes[body])
        for name in ("stature", "bust", "waist", "hips"):
            rules[name][body] = {"minimum": ranges[name][0], "maximum": ranges[name][1]}
        rules["chest"][body] = dict(rules["bust"][body])
        rules["pose"][body] = {"enum": MANNEQUIN_POSES if body == "mannequin" else MADE_POSES}
        rules["outfit"][body] = {"pattern": outfit_pattern(item_pattern(body, sizes, styles))}
        rules["fitmap"][body] = {"enum": ["stretch", "none"] if body == "mannequin" else
                                 ["stretch", "ease", "pressure", "none"]}
        rules["underwear"][body] = {"enum": [] if body == "mannequin" else ["on", "off"]}  # made bodies only
    return rules


def write(document, sizes, styles):
    parameters = document["components"]["parameters"]
    rules = by_body(sizes, styles)
    woman = {"stature": 2, "bust": 3, "waist": 4, "hips": 5}
    default = next(row for row in sizes["female"] if row[0] == "M")
    for key, name in (("Stature", "stature"), ("Bust", "bust"), ("Chest", "chest"), ("Waist", "waist"),
                      ("Hips", "hips")):
        schema = parameters[key]["schema"]
        schema["minimum"] = min(rule["minimum"] for rule in rules[name].values())
        schema["maximum"] = max(rule["maximum"] for rule in rules[name].values())
        if name != "chest":
            schema["default"] = default[woman[name]]
    for key, name in (("Pose", "pose"), ("Fitmap", "fitmap")):
        union = []
        for rule in rules[name].values():
            union += [value for value in rule["enum"] if value not in union]
        parameters[key]["schema"]["enum"] = union
    # A whole outfit of one body's: one body's items may not be mixed with another's (a made
    # body's sized item beside the Mannequin's unsized one is refused, so the document must too).
    outfits = [item + "(," + item + "){0,2}" for item in (item_pattern(body, sizes, styles) for body in BODIES)]
    parameters["Outfit"]["schema"]["pattern"] = "^(|none|" + "|".join(outfits) + ")$"
    # The styles sewn from patterns: a posed made body refuses them (the hooks keep the rule).
    parameters["Outfit"]["x-figment-sewn-styles"] = [name for name, sold, sewn in styles if sewn]
    for key, name in (("Stature", "stature"), ("Bust", "bust"), ("Chest", "chest"), ("Waist", "waist"),
                      ("Hips", "hips"), ("Pose", "pose"), ("Outfit", "outfit"), ("Fitmap", "fitmap"),
                      ("Underwear", "underwear")):
        parameters[key].pop("x-figment-by-sex", None)
        parameters[key]["x-figment-by-body"] = rules[name]
    fit_styles = [name for name, sold, sewn in styles if any(sold.values())]
    parameters["FitStyle"]["schema"]["enum"] = fit_styles
    parameters["FitStyle"]["x-figment-by-sex"] = {
        sex: {"enum": [name for name, sold, sewn in styles if sold.get(sex)]} for sex in ("female", "male")}
    for key, name in (("FitStature", "stature"), ("FitBust", "bust"), ("FitWaist", "waist"), ("FitHips", "hips")):
        by_sex = {sex: rules[name][sex] for sex in ("female", "male")}
        parameters[key]["x-figment-by-sex"] = by_sex
        parameters[key]["schema"]["minimum"] = min(rule["minimum"] for rule in by_sex.values())
        parameters[key]["schema"]["maximum"] = max(rule["maximum"] for rule in by_sex.values())
    # POST's form: the query's schemas, by name.
    form = document["paths"]["/api/render"]["post"]["requestBody"]["content"]["application/x-www-form-urlencoded"]
    for reference in document["paths"]["/api/render"]["get"]["parameters"]:
        parameter = parameters[reference["$ref"].rsplit("/", 1)[1]]
        form["schema"]["properties"][parameter["name"]] = parameter["schema"]


def main():
    with open(DOCUMENT) as text:
        before = text.read()
    document = json.loads(before)
    write(document, chart(), catalogue())
    after = json.dumps(document, indent=2, ensure_ascii=False) + "\n"
    if "--check" in sys.argv[1:]:
        if after != before:
            print("%s: not what scripts/openapi-choices.py writes from scenes/" % DOCUMENT, file=sys.stderr)
            return 1
        return 0
    with open(DOCUMENT, "w") as out:
        out.write(after)
    return 0


if __name__ == "__main__":
    sys.exit(main())
