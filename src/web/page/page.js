// The worksheet in the browser: the problem list, a problem with its statement typeset by KaTeX,
// its values for a variant, an input per answer judged by the server (the same judge as
// `wobble check`), the hint after two wrong tries, and a summary. The URL holds the problem and
// the variant (#/ID/N), so a reload comes back to the same place.
'use strict';

const main = document.getElementById('main');

function el(tag, attrs, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs || {})) {
    if (k === 'class') e.className = v; else e.setAttribute(k, v);
  }
  for (const c of children) e.append(c);
  return e;
}

// Units as a reader writes them: kg m^2/s -> kg m²/s.
function prettyUnit(unit) {
  const sup = {'-': '⁻', '0': '⁰', '1': '¹', '2': '²', '3': '³', '4': '⁴', '5': '⁵', '6': '⁶',
               '7': '⁷', '8': '⁸', '9': '⁹'};
  return unit.replace(/\^(-?\d+)/g, (m, p) => [...p].map(c => sup[c]).join(''));
}

// Text with `code` spans as <code>, the rest as text (never parsed as HTML).
function withCode(text) {
  return text.split('`').map((piece, i) => i % 2 ? el('code', {}, piece) : piece);
}

function typeset(node) {
  renderMathInElement(node, {
    delimiters: [{left: '$', right: '$', display: false}],
    throwOnError: false,
  });
}

async function getJson(url, options) {
  const res = await fetch(url, options);
  const body = await res.json();
  if (!res.ok) throw new Error(body.error || ('HTTP ' + res.status));
  return body;
}

async function showList() {
  const problems = await getJson('api/problems');
  main.replaceChildren(el('h1', {}, 'Problems'),
    el('ul', {class: 'problems'}, ...problems.map(p =>
      el('li', {}, el('a', {href: '#/' + p.id}, p.title), el('span', {class: 'id'}, p.id)))));
}

function parameterRow(p) {
  const name = el('td', {}, '$' + p.latex + '$');
  return el('tr', {}, name, el('td', {}, p.shown || (p.value + (p.unit ? ' ' + prettyUnit(p.unit) : ''))),
            el('td', {class: 'unit'}, p.description));
}

async function showProblem(id, variant) {
  const query = variant ? '?variant=' + variant : '';
  const view = await getJson('api/problems/' + encodeURIComponent(id) + query);
  const state = {right: 0, total: 0};
  const summary = el('p', {class: 'summary'});
  const box = el('input', {type: 'number', min: '1', max: '1000000', value: variant || '',
                           placeholder: 'default', 'aria-label': 'variant number'});
  box.addEventListener('change', () => {
    location.hash = '#/' + id + (box.value ? '/' + box.value : '');
  });
  const statement = el('div', {class: 'statement'}, ...withCode(view.statement));
  const values = el('table', {class: 'values'}, ...view.parameters.map(parameterRow));
  const parts = view.parts.map(part => partView(id, variant, part, state, () => {
    summary.textContent = state.right + ' of ' + state.total + ' answers right';
  }));
  main.replaceChildren(el('h1', {}, view.title), statement,
                       el('div', {class: 'variant'}, 'Variant ', box), values, ...parts, summary);
  typeset(main);
  const first = main.querySelector('.answer input');
  if (first) first.focus({preventScroll: true});
}

function partView(id, variant, part, state, update) {
  const div = el('div', {class: 'part'}, el('p', {}, el('strong', {}, '(' + part.id + ') '),
                                              part.question));
  let wrong = 0;
  const hint = el('div', {class: 'hint', hidden: ''});
  // After the second wrong try in this part, its hint.
  async function wrongTry() {
    if (++wrong < 2 || !part.has_hint || !hint.hidden) return;
    const h = await getJson('api/problems/' + encodeURIComponent(id) + '/hint?part=' +
                            encodeURIComponent(part.id));
    hint.textContent = 'Hint: ' + h.hint;
    hint.hidden = false;
  }
  for (const a of part.answers) {
    state.total += 1;
    const input = el('input', {type: 'text', autocomplete: 'off', spellcheck: 'false',
                               'data-answer': a.name});
    const verdict = el('div', {class: 'verdict', role: 'status'});
    let counted = false;
    input.addEventListener('keydown', async event => {
      if (event.key !== 'Enter' || !input.value.trim()) return;
      try {
        const v = await getJson('api/problems/' + encodeURIComponent(id) + '/check', {
          method: 'POST', headers: {'Content-Type': 'application/json'},
          body: JSON.stringify({part: part.id, name: a.name, answer: input.value,
                                variant: variant ? Number(variant) : null})});
        verdict.className = 'verdict ' + (v.correct ? 'right' : 'wrong');
        verdict.textContent = [v.verdict, ...v.feedback].join(' — ');
        if (v.correct && !counted) { counted = true; state.right += 1; update(); }
        if (!v.correct) await wrongTry();
        if (v.correct) {
          const inputs = [...main.querySelectorAll('.answer input')];
          const next = inputs[inputs.indexOf(input) + 1];
          if (next) next.focus();
        }
      } catch (e) {
        verdict.className = 'verdict wrong';
        verdict.textContent = e.message;
        await wrongTry();  // an answer the judge cannot read is a try too
      }
    });
    const unit = a.unit ? ' [' + prettyUnit(a.unit) + ']' : '';
    const shape = a.shape === 'vector' ? ' (a vector [x, y, z])' :
                  a.shape === 'matrix' ? ' (a matrix [[..], [..], [..]])' : '';
    div.append(el('div', {class: 'answer'}, el('label', {}, a.name + unit + shape), input, verdict));
  }
  for (const absent of part.absent) div.append(el('p', {class: 'unit'}, absent + ' does not exist at these values'));
  div.append(hint);
  return div;
}

async function route() {
  const [, id, variant] = location.hash.split('/');
  try {
    if (id) await showProblem(decodeURIComponent(id), variant); else await showList();
  } catch (e) {
    main.replaceChildren(el('p', {class: 'verdict wrong'}, e.message));
  }
}

window.addEventListener('hashchange', route);
route();
