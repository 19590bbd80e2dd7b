// The grammar's text: a plain textarea over a highlighted copy of it, with
// line numbers, the line of an error marked and lines of a picked part lit.
// (No editor library: the page loads nothing but three.js.)

const KEYWORDS = /^(split|repeat|repeatN|comp|I|T|S|R|nil|colour|rand|randint|choice|tnormal|normal|min|max|abs|sqrt|floor|ceil|round|size|pi|x|y|z|front|back|left|right|top|bottom)$/;

function escape(text) {
  return text.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;');
}

// One line's text as highlighted HTML: comments, strings, numbers, words
// of the language, and the label a rule defines.
function highlightLine(line) {
  let out = '';
  let rest = line;
  const head = /^(\s*)([A-Za-z_][A-Za-z0-9_]*)(?=\s*(\(|:|-->|->|→))/.exec(rest);
  if (head && /-->|->|→/.test(line)) {
    out += escape(head[1]) + '<span class="r">' + escape(head[2]) + '</span>';
    rest = rest.slice(head[0].length);
  }
  const token = /(#.*|\/\/.*)|("(?:[^"\\]|\\.)*")|(\b\d+(?:\.\d+)?(?:e[+-]?\d+)?\b)|([A-Za-z_][A-Za-z0-9_]*)/gy;
  let at = 0;
  while (at < rest.length) {
    token.lastIndex = at;
    const m = token.exec(rest);
    if (!m) {
      out += escape(rest[at]);
      ++at;
      continue;
    }
    if (m[1]) out += '<span class="c">' + escape(m[1]) + '</span>';
    else if (m[2]) out += '<span class="s">' + escape(m[2]) + '</span>';
    else if (m[3]) out += '<span class="n">' + escape(m[3]) + '</span>';
    else out += KEYWORDS.test(m[4]) ? '<span class="k">' + escape(m[4]) + '</span>' : escape(m[4]);
    at = token.lastIndex;
  }
  return out;
}

export class Editor {
  constructor({ text, highlight, gutter, onChange, onLine }) {
    this.area = text;
    this.highlight = highlight;
    this.gutter = gutter;
    this.bad = 0;          // the line of the error shown, 0: none
    this.lit = new Set();  // lines lit for a picked part
    text.addEventListener('input', () => {
      this.render();
      onChange(this.area.value);
    });
    const line = () => onLine(this.area.value.slice(0, this.area.selectionStart).split('\n').length);
    text.addEventListener('click', line);
    text.addEventListener('keyup', (e) => { if (e.key.startsWith('Arrow') || e.key === 'Home' || e.key === 'End') line(); });
    text.addEventListener('keydown', (e) => {
      if (e.key !== 'Tab') return;
      e.preventDefault();  // a tab indents rather than leaving the editor
      document.execCommand('insertText', false, '    ');
    });
  }

  get value() { return this.area.value; }

  set value(text) {
    this.area.value = text;
    this.render();
  }

  markError(line) {
    this.bad = line || 0;
    this.render();
    if (this.bad) this.scrollTo(this.bad);
  }

  light(lines) {
    this.lit = new Set(lines);
    this.render();
    if (lines.length) this.scrollTo(Math.min(...lines));
  }

  scrollTo(line) {
    const height = parseFloat(getComputedStyle(this.area).lineHeight) || 18;
    const box = this.area.closest('#editor');
    const y = (line - 1) * height;
    if (y < box.scrollTop || y > box.scrollTop + box.clientHeight - 2 * height) box.scrollTop = Math.max(0, y - box.clientHeight / 3);
  }

  render() {
    const lines = this.area.value.split('\n');
    const cls = (n) => (n === this.bad ? ' class="bad"' : this.lit.has(n) ? ' class="hit"' : '');
    this.highlight.innerHTML = lines.map((l, i) => `<div${cls(i + 1)}>${highlightLine(l) || ' '}</div>`).join('');
    this.gutter.innerHTML = lines.map((_, i) => `<div${cls(i + 1)}>${i + 1}</div>`).join('');
    // The textarea grows with its text; the pane around it scrolls.
    this.area.style.height = 'auto';
    this.area.style.height = this.area.scrollHeight + 'px';
    this.area.style.width = 'auto';
    this.area.style.width = Math.max(this.area.scrollWidth, this.area.parentElement.clientWidth) + 'px';
  }
}
