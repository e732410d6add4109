// The worksheet in the browser: the problem list, a problem with its statement typeset by KaTeX,
// its values for a variant, its motion in 3-D (view3d.js), an input per answer judged by the
// server (the same judge as `wobble check`), the hint after two wrong tries, and a summary. The
// URL holds the problem and the variant (#/ID/N), so a reload comes back to the same place.
// With the instructor's token in the address (?token=...) or a server started with --reveal,
// each answer shows the key as well.
//
// Written by `wobble page` as one file, the page carries its problem in WOBBLE_DATA (view,
// motion, and the key only if asked for) and needs no server: the statement, values, the 3-D
// view and the questions, without the judge.
'use strict';

const main = document.getElementById('main');
const offline = typeof WOBBLE_DATA !== 'undefined';
const token = new URLSearchParams(location.search).get('token');
// An answer box grows with the lines pasted into it up to this many (a matrix as MATLAB prints
// it, with its name and a blank line, is five); beyond, it scrolls.
const kMostAnswerRows = 8;
let current = null;  // the 3-D view shown, stopped when the page moves on

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

// The unit beside an answer's name, " [rad/s]": as the question asks for it, so where the
// unit would tell the answer (a growth rate's 1/s) the alternatives ("rad/s or 1/s").
function askedUnit(a) { return a.asked_unit ? ' [' + prettyUnit(a.asked_unit) + ']' : ''; }

// An answer's label: its name, its unit as asked, and how it is typed as the server words it
// ("a vector [.., .., ..] along e₁, e₂, e₃"; nothing for a number), as the handout has it.
function answerLabel(a) { return a.name + askedUnit(a) + (a.form ? ' (' + a.form + ')' : ''); }

// Text with `code` spans as <code> and **strong** spans as <strong>, the rest as text (never
// parsed as HTML).
function withCode(text) {
  return text.split('`').flatMap((piece, i) => i % 2 ? [el('code', {}, piece)] :
    piece.split('**').map((part, j) => j % 2 ? el('strong', {}, part) : part));
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
  const scenes = await getJson('api/scenes');
  const list = (items, prefix) => el('ul', {class: 'problems'}, ...items.map(p =>
    el('li', {}, el('a', {href: '#/' + prefix + p.id}, p.title), el('span', {class: 'id'}, p.id))));
  main.replaceChildren(el('h1', {}, 'Problems'), list(problems, ''),
                       el('h2', {}, 'Motions'), list(scenes, 'scene/'));
}

// A motion section: the 3-D view of `motion` (JSON from the server or the file).
function motionSection(motion) {
  current = motionView(motion);
  return el('section', {class: 'motion-section'}, el('h2', {}, 'The motion'), current.element);
}

async function showScene(id) {
  const motion = await getJson('api/scenes/' + encodeURIComponent(id) + '/motion');
  const description = motion.description.trim();  // optional in a scene file
  main.replaceChildren(el('h1', {}, motion.title),
                       ...(description ? [el('div', {class: 'statement'}, ...withCode(description))] : []),
                       motionSection(motion));
  typeset(main);
}

// The key of a problem for an instructor (null for a student: the server refuses without the
// token, and the page does not ask).
async function keyFor(id, query) {
  if (offline) return WOBBLE_DATA.key || null;
  const session = await getJson('api/session' + (token ? '?token=' + encodeURIComponent(token) : ''));
  if (!session.key) return null;
  const sep = query ? '&' : '?';
  return getJson('api/problems/' + encodeURIComponent(id) + '/key' + query +
                 (token ? sep + 'token=' + encodeURIComponent(token) : ''));
}

// A key's number as wobble's text key prints it: 10 significant digits.
function keyNumber(x) {
  return Array.isArray(x) ? '[' + x.map(keyNumber).join(', ') + ']' : String(Number(x.toPrecision(10)));
}

function keyLine(answer) {
  if (answer.absent) {
    return el(
        'div', {class: 'key-answer'},
        'Key: ', el('span', {class: 'key-value'}, 'none at these values'));
  }
  const value = keyNumber(answer.value);
  return el('div', {class: 'key-answer'}, 'Key: ', answer.latex ? '$' + answer.latex + '$ = ' : '',
            el('span', {class: 'key-value'}, value + (answer.unit ? ' ' + prettyUnit(answer.unit) : '')));
}

function parameterRow(p) {
  const name = el('td', {}, '$' + p.latex + '$');
  return el('tr', {}, name, el('td', {}, p.shown || (p.value + (p.unit ? ' ' + prettyUnit(p.unit) : ''))),
            el('td', {class: 'unit'}, p.description));
}

async function showProblem(id, variant) {
  const query = variant ? '?variant=' + variant : '';
  const view = offline ? WOBBLE_DATA.view : await getJson('api/problems/' + encodeURIComponent(id) + query);
  const motion = !view.has_motion ? null : offline ? WOBBLE_DATA.motion :
                 await getJson('api/problems/' + encodeURIComponent(id) + '/motion' + query);
  const key = await keyFor(id, query);
  const state = {right: 0, total: 0};
  const summary = el('p', {class: 'summary'});
  const box = el('input', {type: 'number', min: '1', max: '1000000', value: variant || '',
                           placeholder: 'default', 'aria-label': 'variant number'});
  box.addEventListener('change', () => {
    location.hash = '#/' + id + (box.value ? '/' + box.value : '');
  });
  const statement = el('div', {class: 'statement'}, ...withCode(view.statement));
  const values = el('table', {class: 'values'}, ...view.parameters.map(parameterRow));
  const keyParts = key ? Object.fromEntries(key.parts.map(p => [p.id, p])) : {};
  const parts = view.parts.map(part => partView(id, variant, part, state, keyParts[part.id], () => {
    summary.textContent = state.right + ' of ' + state.total + ' answers right';
  }));
  const variantLine = offline ? el('div', {class: 'variant'}, view.variant ? 'Variant ' + view.variant : '')
                              : el('div', {class: 'variant'}, 'Variant ', box);
  main.replaceChildren(el('h1', {}, view.title), statement, variantLine, values,
                       ...(motion ? [motionSection(motion)] : []), ...parts,
                       ...(offline ? [] : [summary]));
  typeset(main);
  const first = main.querySelector('.answer textarea');
  if (first) first.focus({preventScroll: true});
}

function partView(id, variant, part, state, partKey, update) {
  const div = el('div', {class: 'part'}, el('p', {}, el('strong', {}, '(' + part.id + ') '),
                                              part.question));
  let wrong = 0;
  const hint = el('div', {class: 'hint', hidden: ''});
  // After the second wrong try in this part, its hint.
  async function wrongTry() {
    if (++wrong < 2 || !part.has_hint || !hint.hidden) return;
    const h = await getJson('api/problems/' + encodeURIComponent(id) + '/hint?part=' +
                            encodeURIComponent(part.id));
    // Its math typeset as the question's is.
    hint.replaceChildren('Hint: ', ...withCode(h.hint));
    hint.hidden = false;
    typeset(hint);
  }
  // An answer that does not exist at these values (a slow top's steady precession) is asked as
  // the others are, "none" right: saying so beside it would give the answer away.
  const asked = [
    ...part.answers,
    ...part.absent.map((name, i) => ({name, absent: true, asked_unit: part.absent_units[i]}))
  ];
  for (const a of asked) {
    const keyed = partKey &&
        (a.absent ? (partKey.absent || []).includes(a.name) && a :
                    partKey.answers.find(k => k.name === a.name));
    if (offline) {
      // No judge without the server: the answer's name and unit, and the key if it was asked for.
      div.append(
          el('div', {class: 'answer'}, el('label', {}, answerLabel(a)),
             ...(keyed ? [keyLine(keyed)] : [])));
      continue;
    }
    state.total += 1;
    // A box of one line that keeps line breaks: a matrix pasted as NumPy or MATLAB prints it
    // keeps its rows, where an input would strip them ("-0.75⏎-0.5" becomes the difference
    // "-0.75-0.5"). Enter judges; Shift+Enter starts a new line; the box grows with its lines.
    const input = el('textarea', {rows: '1', autocomplete: 'off', spellcheck: 'false',
                                  'data-answer': a.name});
    input.addEventListener('input', () => {
      input.rows = Math.min(kMostAnswerRows, input.value.split('\n').length);
    });
    const verdict = el('div', {class: 'verdict', role: 'status'});
    let counted = false;
    input.addEventListener('keydown', async event => {
      // An Enter that confirms an input method's composition (a Greek letter typed through an
      // IME) is no request to judge.
      if (event.key !== 'Enter' || event.shiftKey || event.isComposing) return;
      event.preventDefault();
      if (!input.value.trim()) return;
      try {
        const v = await getJson('api/problems/' + encodeURIComponent(id) + '/check', {
          method: 'POST', headers: {'Content-Type': 'application/json'},
          body: JSON.stringify({part: part.id, name: a.name, answer: input.value,
                                variant: variant ? Number(variant) : null})});
        verdict.className = 'verdict ' + (v.correct ? 'right' : 'wrong');
        verdict.textContent = [v.verdict, ...v.feedback].join(' — ');
        if (v.correct && !counted) {
          counted = true;
          state.right += 1;
          update();
        }
        if (!v.correct) await wrongTry();
        if (v.correct) {
          const inputs = [...main.querySelectorAll('.answer textarea')];
          const next = inputs[inputs.indexOf(input) + 1];
          if (next) next.focus();
        }
      } catch (e) {
        verdict.className = 'verdict wrong';
        // The server names the request's field, "answer: .."; under its box the box is that.
        verdict.textContent = e.message.replace(/^answer(: |, )/, '');
        await wrongTry();  // an answer the judge cannot read is a try too
      }
    });
    div.append(
        el('div', {class: 'answer'}, el('label', {}, answerLabel(a)), input, verdict,
           ...(keyed ? [keyLine(keyed)] : [])));
  }
  if (!offline) div.append(hint);
  // No judge to count tries from a file: the hint folded, for the student to open.
  if (offline && part.hint) {
    div.append(el('details', {class: 'hint'}, el('summary', {}, 'Hint'), ...withCode(part.hint)));
  }
  return div;
}

async function route() {
  if (current) current.destroy();
  current = null;
  const [, id, variant] = location.hash.split('/');
  try {
    if (offline) await showProblem(WOBBLE_DATA.view.id, WOBBLE_DATA.view.variant);
    else if (id === 'scene') await showScene(decodeURIComponent(variant));
    else if (id) await showProblem(decodeURIComponent(id), variant);
    else await showList();
  } catch (e) {
    main.replaceChildren(el('p', {class: 'verdict wrong'}, e.message));
  }
}

window.addEventListener('hashchange', route);
route();
