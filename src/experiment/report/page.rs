//! The report as one HTML file: the page's data as JSON, the vendored three.js (its two
//! ES modules and its orbit controls) and uPlot, and the page's own script and style, all
//! embedded so the file opens in a browser without a network.

use serde_json::Value;

/// three.js 0.187.0 as released on npm (`build/three.core.js`, `build/three.module.js`,
/// `examples/jsm/controls/OrbitControls.js`; MIT, `assets/report/three/LICENSE`).
const THREE_CORE: &str = include_str!("../../../assets/report/three/three.core.js");
const THREE_MODULE: &str = include_str!("../../../assets/report/three/three.module.js");
const THREE_ORBIT: &str = include_str!("../../../assets/report/three/OrbitControls.js");
/// uPlot 1.6.32 as released on npm (`dist/`; MIT, `assets/report/uplot/LICENSE`).
const UPLOT: &str = include_str!("../../../assets/report/uplot/uPlot.iife.min.js");
const UPLOT_CSS: &str = include_str!("../../../assets/report/uplot/uPlot.min.css");
const REPORT_JS: &str = include_str!("../../../assets/report/report.js");
const REPORT_CSS: &str = include_str!("../../../assets/report/report.css");

/// Where the 3-D view's 640×480 canvas sits in the page (px from its left and top edge).
pub const VIEW_ORIGIN: (u32, u32) = (0, 40);
/// The 3-D view's size (px).
pub const VIEW_SIZE: (u32, u32) = (640, 480);

/// The page for `title` showing `data`.
pub(super) fn page(title: &str, data: &Value) -> String {
    // `</` inside a script element would end it; in JSON it only occurs in strings, where
    // `<\/` reads the same.
    let data = data.to_string().replace("</", "<\\/");
    let mut html = String::with_capacity(data.len() + 2_400_000);
    html.push_str("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>");
    html.push_str(&escaped(title));
    html.push_str("</title>\n<style>\n");
    html.push_str(UPLOT_CSS);
    html.push('\n');
    html.push_str(REPORT_CSS);
    html.push_str("</style>\n</head>\n<body>\n<h1 id=\"title\"></h1>\n<div id=\"report\"></div>\n");
    for (id, kind, text) in [
        ("report-data", "application/json", data.as_str()),
        ("three-core", "text/plain", THREE_CORE),
        ("three-module", "text/plain", THREE_MODULE),
        ("three-orbit", "text/plain", THREE_ORBIT),
    ] {
        html.push_str(&format!("<script id=\"{id}\" type=\"{kind}\">"));
        html.push_str(text);
        html.push_str("</script>\n");
    }
    html.push_str("<script>");
    html.push_str(UPLOT);
    html.push_str("</script>\n<script type=\"module\">");
    html.push_str(REPORT_JS);
    html.push_str("</script>\n</body>\n</html>\n");
    html
}

/// `text` with the characters HTML gives a meaning escaped.
fn escaped(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn the_page_embeds_everything_and_its_data_cannot_end_its_script() {
        for (name, text) in [
            ("three.core.js", THREE_CORE),
            ("three.module.js", THREE_MODULE),
            ("OrbitControls.js", THREE_ORBIT),
            ("uPlot", UPLOT),
        ] {
            assert!(
                !text.contains("</script"),
                "{name} would end its script element"
            );
        }
        let html = page("a <run> & more", &json!({"info": "note </script> here"}));
        assert!(html.contains("<title>a &lt;run&gt; &amp; more</title>"));
        assert_eq!(html.matches("</script>").count(), 6);
        assert!(html.contains(r#"note <\/script> here"#));
        assert!(
            !html.contains(" src=\"http") && !html.contains("<link"),
            "no network"
        );
    }
}
