#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <vector>

#include "render/common.hpp"
#include "render/handout.hpp"
#include "render/prose.hpp"
#include "render/render.hpp"

namespace wobble {

namespace {
// Statement Markdown to LaTeX: text escaped, $...$ kept as math, **bold** as \textbf.
std::string statement_latex(const std::string& md) {
  std::string out;
  bool math = false, bold = false;
  std::string chunk;
  auto flush = [&] {
    out += math ? chunk : detail::latex_text(chunk);
    chunk.clear();
  };
  for (std::size_t i = 0; i < md.size(); ++i) {
    if (md[i] == '$') {
      flush();
      out += '$';
      math = !math;
    } else if (!math && md[i] == '`') {
      // A code span (a scene's id): typewriter.
      const std::size_t close = md.find('`', i + 1);
      if (close == std::string::npos) {
        chunk += md[i];
        continue;
      }
      flush();
      out += "\\texttt{" + detail::latex_text(md.substr(i + 1, close - i - 1)) + "}";
      i = close;
    } else if (!math && md.compare(i, 2, "**") == 0) {
      flush();
      out += bold ? "}" : "\\textbf{";
      bold = !bold;
      ++i;
    } else {
      chunk += md[i];
    }
  }
  flush();
  if (math) out += '$';
  if (bold) out += '}';
  return out;
}
// A name in typewriter type as typed (latex_text would set Omega_body as a symbol).
std::string texttt_escaped(const std::string& name) {
  std::string out;
  for (const char c : name) out += c == '_' ? std::string("\\_") : std::string(1, c);
  return out;
}

// The one pmatrix in a formula: the text before it, its cells (row-major) and the text after;
// nullopt if the formula has none or more than one.
struct MatrixFormula {
  std::string before, after;
  std::vector<std::vector<std::string>> rows;
};
std::optional<MatrixFormula> split_matrix(const std::string& latex) {
  const std::string open = "\\begin{pmatrix}", close = "\\end{pmatrix}";
  const auto b = latex.find(open);
  const auto e = latex.find(close);
  if (b == std::string::npos || e == std::string::npos || e < b ||
      latex.find(open, b + 1) != std::string::npos) {
    return std::nullopt;
  }
  MatrixFormula m{latex.substr(0, b), latex.substr(e + close.size()), {{}}};
  std::string cell;
  int depth = 0;
  const std::string body = latex.substr(b + open.size(), e - b - open.size());
  for (std::size_t i = 0; i < body.size(); ++i) {
    const char c = body[i];
    if (c == '{') ++depth;
    if (c == '}') --depth;
    if (depth == 0 && c == '&') {
      m.rows.back().push_back(cell);
      cell.clear();
    } else if (depth == 0 && body.compare(i, 2, "\\\\") == 0) {
      m.rows.back().push_back(cell);
      cell.clear();
      m.rows.emplace_back();
      ++i;
    } else {
      cell += c;
    }
  }
  m.rows.back().push_back(cell);
  return m;
}

// The matrix's fractions at full size, its rows spaced apart: in a pmatrix a \frac is set in
// text style, its numerator and denominator in small type; at full size each row would touch
// the next without the space (2ex: below that the strut alone sets it).
// `latex` itself where no cell has a fraction.
std::string fractions_displayed(const std::string& latex, const MatrixFormula& m) {
  const auto has_fraction = [](const std::string& cell) {
    return cell.find("\\frac") != std::string::npos;
  };
  if (std::none_of(m.rows.begin(), m.rows.end(), [&](const auto& row) {
        return std::any_of(row.begin(), row.end(), has_fraction);
      }))
    return latex;
  std::string out = m.before + "\\begin{pmatrix}";
  for (std::size_t i = 0; i < m.rows.size(); ++i) {
    for (std::size_t j = 0; j < m.rows[i].size(); ++j) {
      std::string cell = m.rows[i][j];
      for (auto at = cell.find("\\frac"); at != std::string::npos; at = cell.find("\\frac", at + 6))
        cell.replace(at, 5, "\\dfrac");
      out += (j ? " & " : " ") + cell;
    }
    out += i + 1 < m.rows.size() ? " \\\\[2ex]" : " ";
  }
  return out + "\\end{pmatrix}" + m.after;
}

// A display formula; one with a vector or matrix is shown whole, or entry by entry where the
// whole would have to shrink below readability.
std::string display(const std::string& latex) {
  const auto m = split_matrix(latex);
  if (!m) return "\\fit{" + latex + "}";
  const std::string whole = fractions_displayed(latex, *m);
  std::string entries = m->before.empty() ? "" : "\\fit{" + m->before + "\\text{entry by entry:}}";
  const bool column = std::all_of(m->rows.begin(), m->rows.end(),
                                  [](const auto& r) { return r.size() == 1; });
  for (std::size_t i = 0; i < m->rows.size(); ++i) {
    for (std::size_t j = 0; j < m->rows[i].size(); ++j) {
      const std::string index = column ? fmt::format("{}", i + 1) : fmt::format("{},{}", i + 1, j + 1);
      entries += "\\fit{[\\,\\cdot\\,]_{" + index + "} = " + m->rows[i][j] + "}";
    }
  }
  return "\\fitor{" + whole + "}{" + entries + "}";
}

// A step's formula: after its label, a display; without one, beside the step's number as a
// line of text would stand (not centred on the number's line), and a vector or matrix, a
// display of its own, on the line below the number.
std::string step_display(const std::string& latex, bool unlabelled) {
  if (!unlabelled) return display(latex);
  if (split_matrix(latex)) return "\\leavevmode" + display(latex);
  return "\\fitbeside{" + latex + "}";
}
}  // namespace

std::string detail::matrix_fractions_displayed(const std::string& latex) {
  const auto m = split_matrix(latex);
  return m ? fractions_displayed(latex, *m) : latex;
}

std::string latex_preamble() {
  return std::string("% Generated by wobble; do not edit by hand.\n") +
         "\\documentclass[11pt]{article}\n"
         "\\usepackage[T1]{fontenc}\n\\usepackage[utf8]{inputenc}\n"
         "\\usepackage{amsmath,amssymb}\n\\usepackage[margin=2cm]{geometry}\n";
}

std::string render_handout_latex(const Key& key,
                                 const std::vector<std::pair<std::string, std::string>>& shown,
                                 std::optional<long> variant) {
  using detail::latex_text;
  std::string out = latex_preamble() + "\\pagestyle{plain}\n\\begin{document}\n";
  out += fmt::format("\\section*{{\\raggedright {}}}\n", latex_text(key.title));
  out += variant ? fmt::format("\\noindent Variant {}\\hfill Name: \\rule{{6cm}}{{0.4pt}}\\par\\medskip\n",
                               *variant)
                 : "\\noindent Name: \\rule{6cm}{0.4pt}\\par\\medskip\n";
  out += statement_latex(key.statement) + "\n\n";
  out += "\\begin{center}\\begin{tabular}{lll}\n\\hline\n";
  for (const auto& p : key.parameters) {
    const auto [value, shown_unit] = detail::shown_value(p, shown);
    const std::string unit = shown_unit == "°" ? "^\\circ" : detail::unit_latex(shown_unit);
    out += fmt::format("${}$ & ${}{}$ & {} \\\\\n", p.latex, value, unit,
                       statement_latex(p.description));
  }
  out += "\\hline\n\\end{tabular}\\end{center}\n";
  for (const auto& part : key.parts) {
    out += fmt::format("\\subsection*{{({}) {}}}\n\\vspace{{4cm minus 3cm}}\n", part.id,
                       statement_latex(part.question));
  }
  return out + "\\end{document}\n";
}

std::string render_latex(const Key& key) {
  using detail::latex_text;
  // Prose sets the key's names as its formulas do: w1 as ω₁, I1 as I₁, angles_zxz as typed.
  const detail::ProseNames names = detail::prose_names(key);
  std::string out =
      latex_preamble() +
      "\\usepackage{graphicx}\n"
      "\\setcounter{MaxMatrixCols}{20}\n"
      "% \\fit{math}: a display formula, scaled down only if it is wider than the line, and\n"
      "% never below 70% (smaller is unreadable): a formula still wider is set as a paragraph\n"
      "% of its own, small, where it may break after a + or a - (\\left( and \\right) become\n"
      "% plain delimiters there, which do not make a group TeX cannot break).\n"
      "\\newsavebox{\\fitbox}\n"
      "\\newcommand{\\fit}[1]{\\sbox{\\fitbox}{$\\displaystyle #1$}%\n"
      "\\ifdim\\wd\\fitbox>\\linewidth\\ifdim0.7\\wd\\fitbox>\\linewidth\n"
      "\\begin{flushleft}\\small\\def\\left##1{\\ifx##1.\\else\\mathopen{##1}\\fi}%\n"
      "\\def\\right##1{\\ifx##1.\\else\\mathclose{##1}\\fi}$\\displaystyle #1$\\end{flushleft}%\n"
      "\\else\\begin{center}\\resizebox{\\linewidth}{!}{\\usebox{\\fitbox}}\\end{center}\\fi\n"
      "\\else\\begin{center}\\usebox{\\fitbox}\\end{center}\\fi}\n"
      "% \\fitbeside{math}: a formula where the text stands (beside a step's number) where it\n"
      "% fits the line, else as \\fit.\n"
      "\\newcommand{\\fitbeside}[1]{\\sbox{\\fitbox}{$\\displaystyle #1$}%\n"
      "\\ifdim\\wd\\fitbox>\\linewidth\\fit{#1}\\else\\usebox{\\fitbox}\\fi}\n"
      "% \\fitor{whole}{entries}: a vector or matrix whole if it fits at 70% or more, else entry\n"
      "% by entry.\n"
      "\\newcommand{\\fitor}[2]{\\sbox{\\fitbox}{$\\displaystyle #1$}%\n"
      "\\ifdim0.7\\wd\\fitbox>\\linewidth #2\\else\\fit{#1}\\fi}\n"
      "\\allowdisplaybreaks\n\\begin{document}\n";
  // A long title wraps as a heading does; the id goes on its own line (it cannot hyphenate).
  out += fmt::format("\\section*{{\\raggedright {}}}\n\\noindent\\texttt{{{}}}\\par\\medskip\n",
                     latex_text(key.title) +
                         (key.variant ? fmt::format(" (variant {})", *key.variant) : ""),
                     latex_text(key.problem));
  if (!key.source.empty()) out += "\\noindent\\emph{Source:} " + latex_text(key.source) + "\n\n";
  out += statement_latex(key.statement) + "\n\n\\noindent Parameters: ";
  for (std::size_t i = 0; i < key.parameters.size(); ++i) {
    const auto& p = key.parameters[i];
    out += fmt::format("{}${} = {}$", i ? ", " : "", p.latex, detail::parameter_value_latex(p));
  }
  out += ".\n";
  if (!key.figure.empty()) {
    // The sketch, by the path it was written to (relative paths resolve where pdflatex runs).
    out += "\\begin{center}\\includegraphics[width=0.62\\linewidth]{" + key.figure +
           "}\\end{center}\n";
  }
  for (const auto& part : key.parts) {
    out += fmt::format("\n\\subsection*{{({}) {}}}\n", part.id, statement_latex(part.question));
    for (const auto& a : part.answers) {
      // The name as a symbol where it reads as one, with the name `check --name` takes.
      const auto symbol = detail::answer_symbol_latex(a.name);
      out += "\\noindent" + (symbol ? "$" + *symbol + "$\\quad" : std::string()) +
             "{\\small\\texttt{" + texttt_escaped(a.name) + "}}:\n";
      if (!a.symbolic.empty()) out += display(a.latex) + "\n";
      out += "\\fit{" + std::string(a.symbolic.empty() ? "" : "= ") + value_latex(a.value) +
             detail::unit_latex(a.unit) + "}\n";
      for (const auto& n : a.notes) out += "\\emph{Note:} " + latex_text(n, names) + "\n\n";
    }
    for (std::size_t i = 0; i < part.absent.size(); ++i) {
      const auto symbol = detail::answer_symbol_latex(part.absent[i]);
      out += "\\noindent" + (symbol ? "$" + *symbol + "$\\quad" : std::string()) +
             "{\\small\\texttt{" + texttt_escaped(part.absent[i]) +
             "}}: " + detail::absent_answer_text(part, i) + "\n\n";
    }
    if (!part.steps.empty()) {
      out += "\\paragraph{Steps}\n\\begin{enumerate}\n";
      for (const auto& s : part.steps) {
        const std::string& prose = s.latex.empty() ? s.text : s.label;
        // Step prose is written for a terminal (sqrt, names): as the text key shows it.
        out += "\\item " + latex_text(detail::pretty(prose), names);
        if (!s.latex.empty()) out += step_display(s.latex, prose.empty());
        out += "\n";
      }
      out += "\\end{enumerate}\n";
    }
  }
  out += "\n\\subsection*{Conventions}\n\\begin{itemize}\n";
  for (const auto& n : key.notes) out += "\\item " + latex_text(n, names) + "\n";
  out += "\\end{itemize}\n\\end{document}\n";
  return out;
}

}  // namespace wobble
