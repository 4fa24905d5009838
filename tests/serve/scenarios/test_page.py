#!/usr/bin/env python3
"""The shopper's page in a real browser: headless Chromium (Debian's chromium and
chromium-driver, driven by python3-selenium) loads / from a figment-serve this test
starts, at two window sizes: a phone's (390 x 844 CSS pixels, mobile emulation) and a
desktop's (1280 x 800).

On the phone: the picture of the shopper's made body, a measurement and a garment changed
and the picture changing each time, the fit map's bands, the size advice for the women's M
chart body, and errors in the shopper's words (cm, not metres). At both sizes: measurements
typed, "Advise my size" pressed by keyboard, three pictures of the body in the advised sizes
(loaded, a body drawn in the ease map's blue, captioned with the size names and
"Recommended"), a neighbour size chosen by keyboard and the main picture changing to it, a
turntable of 12 render jobs completing; every control reached by Tab and named for a screen
reader, no sideways scrolling. Every case needs MakeHuman's data (the made body): where the
file system has none, each is skipped before it runs and the script exits 77, ctest's skip.
Screenshots go to SCREENSHOT-FOLDER.

    test_page.py FIGMENT-SERVE SCREENSHOT-FOLDER
"""
import os
import sys

from selenium import webdriver
from selenium.webdriver.chrome.service import Service as ChromeService
from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select, WebDriverWait

from ServeSupport import ServerCase, main, needs_makehuman

SCREENSHOTS = None
WAIT = 600  # s: WebDriverWait's bound, not an assertion on speed (a cold drape takes seconds)


class Browser(ServerCase):
    """A headless Chromium on the class's figment-serve; `arguments` and `emulation` (Chrome's
    mobileEmulation, or None) set its window. `prefix` names its screenshots."""
    server_arguments = ("--workers", "2")
    arguments = ()
    emulation = None
    viewport = None
    prefix = ""

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        options = webdriver.ChromeOptions()
        options.binary_location = "/usr/bin/chromium"
        for argument in ("--headless", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage") + cls.arguments:
            options.add_argument(argument)
        if cls.emulation:
            options.add_experimental_option("mobileEmulation", cls.emulation)
        cls.browser = webdriver.Chrome(service=ChromeService("/usr/bin/chromedriver"), options=options)
        if cls.viewport:  # the page's own size, whatever the headless window's frame takes
            cls.browser.execute_cdp_cmd("Emulation.setDeviceMetricsOverride", dict(cls.viewport, mobile=False))

    @classmethod
    def tearDownClass(cls):
        cls.browser.quit()
        super().tearDownClass()

    def picture_query(self):
        return self.browser.find_element(By.ID, "picture").get_attribute("data-query") or ""

    def wait_for_new_picture(self, before):
        """Waits until the page shows a picture for another request than `before`, loaded."""
        WebDriverWait(self.browser, WAIT).until(
            lambda b: self.picture_query() not in ("", before) and b.execute_script(
                "const i = document.getElementById('picture'); return i.complete && i.naturalWidth > 0;"))
        return self.picture_query()

    def wait_for_picture_naming(self, parts):
        """Waits until the page shows a picture whose request names every one of `parts`, loaded."""
        WebDriverWait(self.browser, WAIT).until(
            lambda b: all(p in self.picture_query() for p in parts) and b.execute_script(
                "const i = document.getElementById('picture'); return i.complete && i.naturalWidth > 0;"))
        return self.picture_query()

    def picture_pixels(self):
        """The shown picture's decoded pixels, summed per channel over a 48x64 sample (the
        page's own image, drawn into a canvas): what the shopper sees, not the URL."""
        return self.browser.execute_script(
            "const i = document.getElementById('picture'); const c = document.createElement('canvas');"
            "c.width = 48; c.height = 64; const g = c.getContext('2d'); g.drawImage(i, 0, 0, 48, 64);"
            "const d = g.getImageData(0, 0, 48, 64).data; const s = [0, 0, 0];"
            "for (let k = 0; k < d.length; k += 4) { s[0] += d[k]; s[1] += d[k + 1]; s[2] += d[k + 2]; }"
            "return s;")

    def assertPictureChanged(self, before):
        after = self.picture_pixels()
        self.assertNotEqual(after, before)
        return after

    def shot(self, name, element_id=None):
        """A screenshot of the window, scrolled to the top or to `element_id`'s element."""
        os.makedirs(SCREENSHOTS, exist_ok=True)
        if element_id:
            self.browser.execute_script("document.getElementById(arguments[0]).scrollIntoView()", element_id)
        else:
            self.browser.execute_script("window.scrollTo(0, 0)")
        self.browser.save_screenshot(os.path.join(SCREENSHOTS, name))

    def assertNoSidewaysScrolling(self):
        width = self.browser.execute_script("return window.innerWidth")
        self.assertLessEqual(self.browser.execute_script("return document.documentElement.scrollWidth"), width)

    def type_measurements(self, values):
        """Types each measurement in cm as a shopper does, leaving the field with Tab (its
        change: the picture follows)."""
        for name, cm in values:
            field = self.browser.find_element(By.ID, name)
            field.clear()
            field.send_keys(cm, Keys.TAB)

    def press(self, element_id, key=Keys.ENTER):
        """Presses a button by keyboard: focus, then Enter (or Space)."""
        button = self.browser.find_element(By.ID, element_id)
        self.browser.execute_script("arguments[0].focus()", button)
        button.send_keys(key)

    def unnamed_controls(self):
        """The page's controls a screen reader would read without a name: an input, select or
        button with no label, aria-label or text; an image without alt text."""
        return self.browser.execute_script(
            "return [...document.querySelectorAll('input, select, button, a, img')].filter((e) => {"
            "  if (e.tagName === 'IMG') return !(e.alt || '').trim();"
            "  const labelled = e.labels && [...e.labels].some((l) => l.textContent.trim());"
            "  return !(labelled || (e.getAttribute('aria-label') || '').trim() || e.textContent.trim());"
            "}).map((e) => e.outerHTML.slice(0, 120));")

    def controls_not_reached_by_tab(self):
        """The visible controls that pressing Tab from the top of the page never focuses."""
        browser = self.browser
        count = browser.execute_script(
            "const all = [...document.querySelectorAll('input, select, button, a[href]')]"
            "  .filter((e) => e.getClientRects().length && !e.disabled);"
            "all.forEach((e, k) => e.dataset.tabCheck = k); document.activeElement.blur(); return all.length;")
        browser.execute_script("window.scrollTo(0, 0); document.body.focus()")
        reached = set()
        for _ in range(count + 5):
            ActionChains(browser).send_keys(Keys.TAB).perform()
            reached.add(browser.execute_script("return document.activeElement.dataset.tabCheck"))
        return [k for k in range(count) if str(k) not in reached]

    def card_pictures(self):
        """Per advice card: [size, caption text, loaded, pixels unlike the corner's, ease-map
        blue pixels], each picture decoded at its own size."""
        return self.browser.execute_script(
            "return [...document.querySelectorAll('#advice-sizes li')].map((card) => {"
            "  const i = card.querySelector('img'); const loaded = i.complete && i.naturalWidth > 0;"
            "  let drawn = 0, blue = 0;"
            "  if (loaded) { const c = document.createElement('canvas'); c.width = i.naturalWidth;"
            "    c.height = i.naturalHeight; const g = c.getContext('2d'); g.drawImage(i, 0, 0);"
            "    const d = g.getImageData(0, 0, c.width, c.height).data;"
            "    for (let k = 0; k < d.length; k += 4) { const s = d[k] + d[k + 1] + d[k + 2];"
            "      if (Math.abs(d[k] - d[0]) + Math.abs(d[k + 1] - d[1]) + Math.abs(d[k + 2] - d[2]) > 30) drawn++;"
            "      if (s > 60 && d[k + 2] > 0.8 * s) blue++; } }"
            "  return [card.dataset.size, card.querySelector('figcaption').innerText, loaded, drawn, blue]; });")

    def frames(self):
        """The turntable's frames: [data-view, src, loaded]."""
        return self.browser.execute_script(
            "return [...document.querySelectorAll('#turntable-frames img')].map((i) =>"
            "  [i.dataset.view, i.getAttribute('src') || '', i.dataset.loaded === 'yes' && i.naturalWidth > 0]);")

    def frame_pixels(self, index):
        return self.browser.execute_script(
            "const i = document.querySelectorAll('#turntable-frames img')[arguments[0]];"
            "const c = document.createElement('canvas'); c.width = 48; c.height = 64; const g = c.getContext('2d');"
            "g.drawImage(i, 0, 0, 48, 64); return [...g.getImageData(0, 0, 48, 64).data];", index)

    def advice_pick_and_turntable(self, measurements, style):
        """The shopper's journey: measurements typed, advice asked by keyboard, three sizes seen
        on their body, a neighbour worn in the main picture, a turntable of it."""
        browser = self.browser
        browser.get(self.server.url)
        first = self.wait_for_new_picture("")
        self.type_measurements(measurements)
        self.wait_for_picture_naming(["%s=%.3f" % (name, int(cm) / 100) for name, cm in measurements])
        Select(browser.find_element(By.ID, "fit-style")).select_by_value(style)
        self.press("advise")
        # Until the three pictures are loaded, or the advice or a picture said why not.
        WebDriverWait(browser, WAIT).until(lambda b: b.execute_script(
            "const cards = [...document.querySelectorAll('#advice-sizes li')];"
            "const advice = document.getElementById('advice').textContent;"
            "return cards.some((c) => c.querySelector('.error'))"
            "  || (cards.length === 0 && advice !== '' && !advice.startsWith('Trying'))"
            "  || (cards.length > 0 && cards.every((c) => { const i = c.querySelector('img');"
            "       return i.complete && i.naturalWidth > 0; }));"))
        self.assertEqual(len(self.card_pictures()), 3, browser.find_element(By.ID, "advice").text)
        summary = browser.find_element(By.ID, "advice").text
        self.assertIn("Recommended: ", summary)
        recommended = summary.split("Recommended: ", 1)[1].split()[0].rstrip(".")
        cards = self.card_pictures()
        sizes = [c[0] for c in cards]
        self.assertIn(recommended, sizes)
        catalogue = self.server.json("/api/catalogue")[1]
        chart = next(s for s in catalogue["made"]["styles"] if s["name"] == style)["sizes"]["female"]
        self.assertEqual(sizes, sorted(sizes, key=chart.index))  # smallest first
        for size, caption, loaded, drawn, blue in cards:
            self.assertTrue(loaded, size)
            self.assertTrue(caption.startswith(size), caption)
            self.assertEqual("Recommended" in caption, size == recommended, caption)
            self.assertGreater(drawn, 5000, (size, drawn))  # a body, not an empty backdrop
            self.assertGreater(blue, 200, (size, blue))     # the cloth off the skin, in the ease map's blue
        self.assertEqual(
            [browser.find_element(By.CSS_SELECTOR, "#advice-sizes li[data-size='%s'] img" % s).get_attribute("src")
             .count("outfit=%s%%3A%s%%3A" % (style, s)) for s in sizes], [1, 1, 1])
        self.assertFalse(browser.find_element(By.ID, "ease-legend").get_attribute("hidden"))
        # Each picture's alt text names the body, the garment and its size.
        for s in sizes:
            alt = browser.find_element(By.CSS_SELECTOR, "#advice-sizes li[data-size='%s'] img" % s).get_attribute("alt")
            self.assertIn("women's body of height %s cm" % measurements[0][1], alt)
            self.assertIn("hips %s cm" % measurements[3][1], alt)
            self.assertIn("the %s in size %s" % (style, s), alt)
        self.assertEqual(self.unnamed_controls(), [])
        self.assertNoSidewaysScrolling()
        self.shot(self.prefix + "advice.png", "fit")

        # A neighbour, not the size worn now: the main picture changes to it.
        worn = Select(browser.find_element(By.ID, "size-0")).first_selected_option.get_attribute("value")
        neighbour = next(s for s in sizes if s not in (recommended, worn))
        before, pixels = self.picture_query(), self.picture_pixels()
        button = browser.find_element(By.CSS_SELECTOR, "#advice-sizes li[data-size='%s'] button" % neighbour)
        browser.execute_script("arguments[0].focus()", button)
        button.send_keys(Keys.SPACE)
        chosen = self.wait_for_new_picture(before)
        self.assertIn("outfit=%s%%3A%s%%3A" % (style, neighbour), chosen)
        self.assertEqual(Select(browser.find_element(By.ID, "size-0")).first_selected_option.get_attribute("value"),
                         neighbour)
        self.assertPictureChanged(pixels)
        self.assertIn("the %s in %s" % (style, neighbour), browser.find_element(By.ID, "picture").get_attribute("alt"))
        self.assertIn("chosen", browser.find_element(
            By.CSS_SELECTOR, "#advice-sizes li[data-size='%s']" % neighbour).get_attribute("class"))
        self.assertEqual(browser.find_element(By.ID, "error").text, "")

        self.press("turntable")
        status = browser.find_element(By.ID, "turntable-status")
        WebDriverWait(browser, WAIT).until(
            lambda b: "All 12 views are ready" in status.text or "could not" in status.text
            or b.find_element(By.ID, "error").text)
        self.assertIn("All 12 views are ready", status.text)
        frames = self.frames()
        self.assertEqual([f[0] for f in frames], ["%d,5" % (30 * k) for k in range(12)])
        for view, src, loaded in frames:
            self.assertTrue(loaded, view)
            self.assertIn("view=%s.0,5.0" % view.split(",")[0], src)
            self.assertIn("outfit=%s:%s:" % (style, neighbour), src)
        self.assertNotEqual(self.frame_pixels(0), self.frame_pixels(3))  # front and side differ
        self.assertNoSidewaysScrolling()
        self.shot(self.prefix + "turntable.png", "turntable")
        self.assertEqual(self.unnamed_controls(), [])
        self.assertEqual(self.controls_not_reached_by_tab(), [])


class PhonePage(Browser):
    """A phone's screen: 390 CSS pixels wide, as the page is laid out there."""
    arguments = ("--window-size=600,1300",)
    emulation = {"deviceMetrics": {"width": 390, "height": 844, "pixelRatio": 1}}
    prefix = "serve-page-"

    @needs_makehuman
    def test_advice_in_pictures_a_size_chosen_and_a_turntable(self):
        self.advice_pick_and_turntable((("stature", "170"), ("bust", "92"), ("waist", "76"), ("hips", "102")),
                                       "dress")

    @needs_makehuman
    def test_errors_say_what_to_change_in_cm(self):
        browser = self.browser
        browser.get(self.server.url)
        self.wait_for_new_picture("")
        hips = self.server.json("/api/catalogue")[1]["made"]["measurements"]["female"]["hips"]
        over = round(hips["max"] * 100) + 10
        self.type_measurements((("hips", str(over)),))
        error = browser.find_element(By.ID, "error")
        WebDriverWait(browser, WAIT).until(lambda b: error.text)
        self.assertEqual(error.text, "Hips: %d cm is outside what we can show (%d to %d cm)."
                         % (over, round(hips["min"] * 100), round(hips["max"] * 100)))
        # Each within its range, but not one body together: MakeHuman's nearest, in cm.
        self.type_measurements((("bust", "76"), ("waist", "88"), ("hips", "110")))
        WebDriverWait(browser, WAIT).until(lambda b: error.text.startswith("Waist"))
        self.assertRegex(error.text, r"^Waist: 88 cm cannot be combined with your other measurements; "
                                     r"the nearest that works with them is \d+ cm\.$")
        self.press("advise")
        advice = browser.find_element(By.ID, "advice")
        WebDriverWait(browser, WAIT).until(lambda b: advice.text.startswith("Waist"))
        self.assertEqual(advice.text, error.text)  # the advice's 422 says the same
        self.assertEqual(browser.find_elements(By.CSS_SELECTOR, "#advice-sizes li"), [])

    @needs_makehuman
    def test_changing_a_measurement_and_a_garment_changes_the_picture(self):
        browser = self.browser
        browser.get(self.server.url)
        first = self.wait_for_new_picture("")
        self.assertIn("outfit=dress%3AM", first)
        self.assertEqual(browser.find_element(By.ID, "error").text, "")
        pixels = self.picture_pixels()
        self.assertGreater(sum(pixels), 0)
        self.shot("serve-page.png")
        # Narrower than the viewport: usable on a phone without sideways scrolling.
        self.assertEqual(browser.execute_script("return window.innerWidth"), 390)
        self.assertNoSidewaysScrolling()

        hips = browser.find_element(By.ID, "hips")
        hips.clear()
        hips.send_keys("100")
        browser.execute_script("arguments[0].dispatchEvent(new Event('change'))", hips)
        second = self.wait_for_new_picture(first)
        self.assertIn("hips=1.000", second)
        pixels = self.assertPictureChanged(pixels)

        Select(browser.find_element(By.ID, "style-0")).select_by_value("tshirt")
        Select(browser.find_element(By.ID, "style-1")).select_by_value("skirt")
        Select(browser.find_element(By.ID, "size-1")).select_by_value("L")
        third = self.wait_for_new_picture(second)
        self.assertIn("outfit=tshirt%3AM%3Ad9d9d1%2Cskirt%3AL%3A8c1f33", third)
        # The 3D download is the same outfit as glTF binary.
        self.assertTrue(browser.find_element(By.ID, "glb").get_attribute("href").endswith(third + "&format=glb"))
        pixels = self.assertPictureChanged(pixels)
        self.shot("serve-page-outfit.png")

        browser.find_element(By.ID, "turn-right").click()
        turned = self.wait_for_new_picture(third)
        self.assertIn("view=30%2C5", turned)
        pixels = self.assertPictureChanged(pixels)
        self.assertEqual(browser.find_element(By.ID, "error").text, "")
        self.shot("serve-page-turned.png")

        # The base layer is on until the shopper unticks it (by its label, as a reader would):
        # seen with nothing else worn.
        Select(browser.find_element(By.ID, "style-1")).select_by_value("")
        Select(browser.find_element(By.ID, "style-0")).select_by_value("")
        dressed = self.wait_for_picture_naming(["outfit=none"])
        self.assertNotIn("underwear", dressed)
        pixels = self.picture_pixels()
        browser.find_element(By.XPATH, "//label[contains(., 'Underwear')]").click()
        self.wait_for_picture_naming(["outfit=none", "underwear=off"])
        pixels = self.assertPictureChanged(pixels)

        # A shop's own garment, sewn from its size's pattern, is chosen as any other; a drape
        # at rest says nothing more, and one that tore or did not settle says so in words.
        Select(browser.find_element(By.ID, "style-0")).select_by_value("tee")
        sewn = self.wait_for_picture_naming(["outfit=tee%3AM"])
        self.assertPictureChanged(pixels)
        self.assertEqual(browser.find_element(By.ID, "error").text, "")
        self.assertEqual(browser.find_element(By.ID, "drape-note").text, "", sewn)
        for drape, words in (("torn", "did not drape cleanly"), ("restless", "not quite settled"), ("rest", "")):
            note = browser.execute_script("return drapeNote(arguments[0])", drape)
            if words:
                self.assertIn(words, note, drape)
            else:
                self.assertEqual(note, "", drape)

    def band_pixels(self):
        """(warm, blue): the shown picture's pixels in the fit map's red to yellow bands (no
        blue in them) and in its blue band (blue alone), at the picture's own size. Neither
        the skin, the grey T-shirt nor the dark red skirt is either."""
        return self.browser.execute_script(
            "const i = document.getElementById('picture'); const c = document.createElement('canvas');"
            "c.width = i.naturalWidth; c.height = i.naturalHeight; const g = c.getContext('2d');"
            "g.drawImage(i, 0, 0); const d = g.getImageData(0, 0, c.width, c.height).data;"
            "let warm = 0, blue = 0;"
            "for (let k = 0; k < d.length; k += 4) { const s = d[k] + d[k + 1] + d[k + 2]; if (s <= 60) continue;"
            "  if (d[k + 2] < 0.08 * s && d[k] > 0.45 * s) warm++; if (d[k + 2] > 0.8 * s) blue++; }"
            "return [warm, blue];")

    @needs_makehuman
    def test_the_fit_map_colours_the_garments_by_their_stretch(self):
        browser = self.browser
        browser.get(self.server.url)
        first = self.wait_for_new_picture("")
        Select(browser.find_element(By.ID, "style-0")).select_by_value("tshirt")
        Select(browser.find_element(By.ID, "size-0")).select_by_value("S")
        Select(browser.find_element(By.ID, "style-1")).select_by_value("skirt")
        dressed = self.wait_for_new_picture(first)
        self.assertNotIn("fitmap", dressed)
        self.assertEqual(self.band_pixels(), [0, 0])
        self.assertTrue(browser.find_element(By.ID, "fitmap-legend").get_attribute("hidden"))
        browser.find_element(By.ID, "fitmap").click()
        mapped = self.wait_for_new_picture(dressed)
        self.assertIn("fitmap=stretch", mapped)
        warm, blue = self.band_pixels()
        # Most of the cloth hangs at rest (blue); the skirt's waistband holds it up, stretched.
        self.assertGreater(blue, 2000, (warm, blue))
        self.assertGreater(warm, 20, (warm, blue))
        self.assertFalse(browser.find_element(By.ID, "fitmap-legend").get_attribute("hidden"))
        self.assertEqual(browser.find_element(By.ID, "error").text, "")
        self.shot("serve-page-fitmap.png")

    @needs_makehuman
    def test_size_advice_names_the_chart_bodys_own_size(self):
        browser = self.browser
        browser.get(self.server.url)
        self.wait_for_new_picture("")
        self.type_measurements((("stature", "168"), ("bust", "88"), ("waist", "72"), ("hips", "96")))
        Select(browser.find_element(By.ID, "fit-style")).select_by_value("pencil")
        browser.find_element(By.ID, "advise").click()
        advice = browser.find_element(By.ID, "advice")
        WebDriverWait(browser, WAIT).until(lambda b: "Recommended" in advice.text or "Trying" not in advice.text)
        self.assertIn("Recommended: M", advice.text)
        card = browser.find_element(By.CSS_SELECTOR, "#advice-sizes li[data-size='M'] figcaption")
        self.assertEqual(card.text.split("\n"), ["M", "Recommended", "fits everywhere"])
        self.assertNoSidewaysScrolling()


class DesktopPage(Browser):
    """A desktop's window, 1280 x 800."""
    arguments = ("--window-size=1280,800",)
    viewport = {"width": 1280, "height": 800, "deviceScaleFactor": 1}
    prefix = "serve-page-desktop-"

    @needs_makehuman
    def test_advice_in_pictures_a_size_chosen_and_a_turntable(self):
        self.assertEqual(self.browser.execute_script("return [window.innerWidth, window.innerHeight]"), [1280, 800])
        self.advice_pick_and_turntable((("stature", "164"), ("bust", "84"), ("waist", "68"), ("hips", "92")),
                                       "dress")

if __name__ == "__main__":
    ServerCase.executable = sys.argv.pop(1)
    SCREENSHOTS = sys.argv.pop(1)
    main()
