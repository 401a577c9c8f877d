// The layout docs/architecture.md draws, held against the code: every include points down the layers (the
// planning core names no planner, no planner includes another), every file's namespace is its module
// folder's, and no function in src/ runs over kMaxFunctionLines. The modules are read from the folders
// (Modules); all of it reads the sources as text, nothing is compiled.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

const fs::path kSource = PHYSLTL_SOURCE_DIR;

// The modules of a source tree, read from its folders: a module is a folder under src/ with a
// CMakeLists.txt, named by its path under src/ ("planning", "planners/knowledge"); its public headers are
// include/physltl/<that path>/, its namespace physltl::<that path with / as ::>. A planner is a module
// folder directly under src/planners/. Nothing here names a module by hand.
class Modules {
 public:
  explicit Modules(const fs::path& root) {
    if (!fs::exists(root / "src")) return;
    for (const auto& entry : fs::recursive_directory_iterator(root / "src")) {
      if (entry.is_regular_file() && entry.path().filename() == "CMakeLists.txt" && entry.path().parent_path() != root / "src") {
        names_.insert(fs::relative(entry.path().parent_path(), root / "src").generic_string());
      }
    }
  }

  const std::set<std::string>& names() const { return names_; }

  std::set<std::string> planners() const {
    std::set<std::string> found;
    for (const std::string& name : names_) {
      if (name.rfind("planners/", 0) == 0 && name.find('/', 9) == std::string::npos) found.insert(name);
    }
    return found;
  }

  // The module a path of the tree ("src/...", "include/physltl/...") or a public include ("physltl/...")
  // belongs to: the deepest module folder holding it; empty for none.
  std::string of(const std::string& path) const {
    std::string rest;
    for (const std::string root : {"src/", "include/physltl/", "physltl/"}) {
      if (path.rfind(root, 0) == 0) rest = path.substr(root.size());
    }
    for (std::string folder = fs::path(rest).parent_path().generic_string(); !folder.empty();
         folder = fs::path(folder).parent_path().generic_string()) {
      if (names_.contains(folder)) return folder;
    }
    return "";
  }

  static std::string namespace_of(const std::string& module) {
    std::string name = "physltl::" + module;
    for (std::size_t slash; (slash = name.find('/')) != std::string::npos;) name.replace(slash, 1, "::");
    return name;
  }

 private:
  std::set<std::string> names_;
};

const Modules& modules() {
  static const Modules found(kSource);
  return found;
}

// Each layer with the modules it may include, directly or through another (docs/architecture.md). The
// planners are not listed: each may include the planning core, and the registry above them ("planners")
// every one of them, whatever folders src/planners holds.
const std::map<std::string, std::set<std::string>>& allowed() {
  static const std::map<std::string, std::set<std::string>> table = [] {
    std::map<std::string, std::set<std::string>> direct = {
        {"base", {}},
        {"geometry", {"base"}},
        {"ltl", {}},
        {"scenario", {"geometry", "ltl"}},
        {"knowledge", {"scenario"}},
        {"physics", {"scenario"}},
        {"decomposition", {"scenario"}},
        {"render", {"scenario"}},
        {"planning", {"knowledge", "physics", "decomposition"}},
        {"planners", {}},
        {"execution", {"planning"}},
        {"common", {"scenario"}},
        {"setup", {"common", "planners"}},
        {"campaign", {"setup", "execution"}},
        {"app", {"campaign", "render"}},
    };
    for (const std::string& planner : modules().planners()) {
      direct[planner] = {"planning"};
      direct["planners"].insert(planner);
    }
    // The closure: a module may include whatever the modules below it may.
    std::map<std::string, std::set<std::string>> closure;
    for (const auto& [module, below] : direct) {
      std::vector<std::string> open(below.begin(), below.end());
      std::set<std::string>& reach = closure[module];
      while (!open.empty()) {
        const std::string next = open.back();
        open.pop_back();
        if (!reach.insert(next).second) continue;
        for (const std::string& further : direct.at(next)) open.push_back(further);
      }
    }
    return closure;
  }();
  return table;
}

std::vector<fs::path> sources_under(const fs::path& root, const std::vector<std::string>& folders) {
  std::vector<fs::path> files;
  for (const std::string& folder : folders) {
    if (!fs::exists(root / folder)) continue;
    for (const auto& entry : fs::recursive_directory_iterator(root / folder)) {
      const std::string extension = entry.path().extension().string();
      if (entry.is_regular_file() && (extension == ".cpp" || extension == ".h")) files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<fs::path> sources_under(const std::vector<std::string>& folders) { return sources_under(kSource, folders); }

std::string read(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string lines_of(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += item + "\n";
  return text;
}

// The physltl/... headers a file includes, with their line numbers.
std::vector<std::pair<int, std::string>> public_includes_with_lines(const fs::path& file) {
  static const std::regex include(R"re(^\s*#include\s+"(physltl/[^"]+)")re");
  std::vector<std::pair<int, std::string>> found;
  std::istringstream lines(read(file));
  int number = 0;
  for (std::string line; std::getline(lines, line);) {
    ++number;
    std::smatch m;
    if (std::regex_search(line, m, include)) found.emplace_back(number, m[1]);
  }
  return found;
}

std::vector<std::string> public_includes(const fs::path& file) {
  std::vector<std::string> found;
  for (const auto& [line, header] : public_includes_with_lines(file)) found.push_back(header);
  return found;
}

TEST(Layers, EveryModuleFolderIsALayerOfTheTable) {
  for (const std::string& module : modules().names()) EXPECT_TRUE(allowed().contains(module)) << "src/" << module;
  EXPECT_TRUE(modules().planners().contains("planners/knowledge"));
  EXPECT_TRUE(modules().planners().contains("planners/ompl"));
}

TEST(Layers, EveryIncludeOfAModulePointsToItselfOrALowerModule) {
  std::vector<std::string> wrong;
  for (const fs::path& file : sources_under({"src", "include"})) {
    const std::string path = fs::relative(file, kSource).generic_string();
    const std::string module = modules().of(path);
    ASSERT_TRUE(allowed().contains(module)) << path << " belongs to no module of the table";
    for (const auto& [line, header] : public_includes_with_lines(file)) {
      const std::string to = modules().of(header);
      if (to != module && !allowed().at(module).contains(to)) {
        wrong.push_back(path + ":" + std::to_string(line) + ": " + module + " includes " + header + " (" + to + ")");
      }
    }
  }
  EXPECT_TRUE(wrong.empty()) << lines_of(wrong);
}

// The includes by which a planner's files (its folder and its public headers) reach another planner.
std::vector<std::string> includes_between_planners(const fs::path& root, const Modules& tree) {
  std::vector<std::string> wrong;
  for (const fs::path& file : sources_under(root, {"src/planners", "include/physltl/planners"})) {
    const std::string path = fs::relative(file, root).generic_string();
    const std::string from = tree.of(path);
    if (!tree.planners().contains(from)) continue;
    for (const auto& [line, header] : public_includes_with_lines(file)) {
      const std::string to = tree.of(header);
      if (to != from && tree.planners().contains(to)) wrong.push_back(path + ":" + std::to_string(line) + ": " + from + " includes " + to);
    }
  }
  return wrong;
}

TEST(Layers, ThePlanningCoreNamesNoPlannerAndNoPlannerAnother) {
  for (const std::string& planner : modules().planners()) {
    EXPECT_FALSE(allowed().at("planning").contains(planner)) << planner;
    EXPECT_FALSE(allowed().at("execution").contains(planner)) << planner;
  }
  EXPECT_FALSE(allowed().at("execution").contains("planners"));
  const std::vector<std::string> wrong = includes_between_planners(kSource, modules());
  EXPECT_TRUE(wrong.empty()) << lines_of(wrong);
  // Private headers are reached by quoted names relative to their own folder, never by climbing out of it.
  const std::regex climbing(R"re(^\s*#include\s+"\.\./)re");
  for (const fs::path& file : sources_under({"src"})) {
    std::istringstream lines(read(file));
    for (std::string line; std::getline(lines, line);) {
      EXPECT_FALSE(std::regex_search(line, climbing)) << file << ": " << line;
    }
  }
}

// A public header is one another module uses: included from another module's code, or from a public
// header that is itself needed. The rest belong in their module's own folder.
TEST(Layers, EveryPublicHeaderIsOneAnotherModuleUses) {
  std::map<std::string, std::vector<std::string>> headers;  // physltl/... -> its own physltl/... includes
  for (const fs::path& file : sources_under({"include"})) {
    headers[fs::relative(file, kSource / "include").generic_string()] = public_includes(file);
  }
  std::set<std::string> needed;
  for (const fs::path& file : sources_under({"src"})) {
    const std::string module = modules().of(fs::relative(file, kSource).generic_string());
    for (const std::string& header : public_includes(file)) {
      if (modules().of(header) != module) needed.insert(header);
    }
  }
  for (const auto& [header, includes] : headers) {
    for (const std::string& other : includes) {
      if (modules().of(other) != modules().of(header)) needed.insert(other);
    }
  }
  for (bool grew = true; grew;) {
    grew = false;
    for (const std::string& header : std::vector<std::string>(needed.begin(), needed.end())) {
      for (const std::string& other : headers[header]) grew = needed.insert(other).second || grew;
    }
  }
  std::string unused;
  for (const auto& [header, includes] : headers) {
    if (!needed.contains(header)) unused += header + "\n";
  }
  EXPECT_TRUE(unused.empty()) << "public headers no other module uses:\n" << unused;
}

// src/app's folders, each with the folders it may include (docs/architecture.md): no two include each
// other.
const std::map<std::string, std::set<std::string>> kAppFolders = {
    {"import", {}},
    {"views", {}},
    {"pipeline", {"views"}},
    {"scenario_test", {"pipeline", "views"}},
    {"cli", {}},
    {"commands", {"cli", "scenario_test", "pipeline", "views", "import"}},
    {"", {"cli"}},  // main.cpp
};

TEST(Layers, EveryAppFolderIncludesOnlyTheFoldersBelowIt) {
  const std::regex include(R"re(^\s*#include\s+"([^"]+)")re");
  std::string wrong;
  for (const fs::path& file : sources_under({"src/app"})) {
    const fs::path relative = fs::relative(file, kSource / "src/app");
    const std::string folder = relative.has_parent_path() ? relative.begin()->string() : "";
    ASSERT_TRUE(kAppFolders.contains(folder)) << file << ": a folder of src/app the table does not know";
    std::istringstream lines(read(file));
    for (std::string line; std::getline(lines, line);) {
      std::smatch m;
      if (!std::regex_search(line, m, include) || m[1].str().rfind("physltl/", 0) == 0) continue;
      const std::string target = m[1].str();
      const auto slash = target.find('/');
      // A bare name is a file of the same folder.
      const std::string to = slash == std::string::npos ? folder : target.substr(0, slash);
      if (to != folder && !kAppFolders.at(folder).contains(to)) wrong += relative.generic_string() + " includes " + target + "\n";
    }
  }
  EXPECT_TRUE(wrong.empty()) << wrong;
}

// The text with comments, string and character literals blanked (newlines kept), so that braces count.
std::string code_only(const std::string& text) {
  std::string code = text;
  enum class In { kCode, kLineComment, kBlockComment, kString, kChar, kRawString } in = In::kCode;
  std::string raw_end;
  for (std::size_t i = 0; i < code.size(); ++i) {
    const char c = text[i];
    const char next = i + 1 < text.size() ? text[i + 1] : '\0';
    const auto blank = [&](std::size_t at) {
      if (code[at] != '\n') code[at] = ' ';
    };
    switch (in) {
      case In::kCode:
        if (c == '/' && next == '/') in = In::kLineComment, blank(i);
        else if (c == '/' && next == '*') in = In::kBlockComment, blank(i);
        else if (c == 'R' && next == '"' && (i == 0 || !std::isalnum(static_cast<unsigned char>(text[i - 1])))) {
          const std::size_t open = text.find('(', i);
          raw_end = ")" + text.substr(i + 2, open - i - 2) + "\"";
          in = In::kRawString;
        } else if (c == '"') in = In::kString;
        else if (c == '\'' && !(i > 0 && std::isalnum(static_cast<unsigned char>(text[i - 1])))) in = In::kChar;
        break;
      case In::kLineComment:
        if (c == '\n') in = In::kCode;
        else blank(i);
        break;
      case In::kBlockComment:
        blank(i);
        if (c == '*' && next == '/') blank(i + 1), ++i, in = In::kCode;
        break;
      case In::kString:
      case In::kChar:
        if (c == '\\') {
          blank(i), blank(i + 1), ++i;
        } else if (c == (in == In::kString ? '"' : '\'')) {
          in = In::kCode;
        } else {
          blank(i);
        }
        break;
      case In::kRawString:
        if (text.compare(i, raw_end.size(), raw_end) == 0) {
          for (std::size_t k = 0; k + 1 < raw_end.size(); ++k) blank(i + k);
          i += raw_end.size() - 1;
          in = In::kCode;
        } else {
          blank(i);
        }
        break;
    }
  }
  return code;
}

// Whether `head` assigns outside its parentheses (`const int k[] = {`): an initializer, not a function.
bool assigns_outside_parentheses(const std::string& head) {
  int depth = 0;
  for (std::size_t i = 0; i < head.size(); ++i) {
    const char c = head[i];
    if (c == '(' || c == '[') ++depth;
    else if (c == ')' || c == ']') --depth;
    else if (c == '=' && depth == 0) {
      const char before = i > 0 ? head[i - 1] : ' ', after = i + 1 < head.size() ? head[i + 1] : ' ';
      const bool comparison = before == '=' || before == '!' || before == '<' || before == '>' || after == '=';
      if (!comparison && head.rfind("operator", i) == std::string::npos) return true;
    }
  }
  return false;
}

struct FunctionLength {
  std::string where;  // file:line of its first line
  std::string head;   // its signature, shortened
  int lines = 0;      // from the signature's first line to the closing brace
};

// The functions of a source file (namespace or class scope; lambdas and blocks count with the function
// around them), by brace matching over the code without comments and literals.
std::vector<FunctionLength> functions_of(const fs::path& file) {
  const std::string code = code_only(read(file));
  enum class Scope { kNamespace, kType, kFunction, kOther };
  std::vector<Scope> scopes;
  std::vector<std::size_t> starts;  // where each open scope's head began
  std::vector<FunctionLength> found;
  std::size_t head_start = 0;
  const auto line_at = [&](std::size_t at) { return static_cast<int>(std::count(code.begin(), code.begin() + static_cast<long>(at), '\n')) + 1; };
  const std::regex type_head(R"(^\s*(template\s*<.*>\s*)?(namespace|class|struct|union|enum)\b|^\s*extern\s*$)");
  for (std::size_t i = 0; i < code.size(); ++i) {
    const char c = code[i];
    if (c == ';') {
      if (scopes.empty() || scopes.back() != Scope::kFunction) head_start = i + 1;
    } else if (c == '{') {
      const bool in_function = std::find(scopes.begin(), scopes.end(), Scope::kFunction) != scopes.end();
      std::string head = code.substr(head_start, i - head_start);
      while (!head.empty() && std::isspace(static_cast<unsigned char>(head.front()))) head.erase(0, 1), ++head_start;
      Scope scope = Scope::kOther;
      if (in_function) scope = Scope::kOther;  // a block or a lambda: part of the function around it
      else if (std::regex_search(head, type_head)) scope = head.rfind("namespace", 0) == 0 || head.rfind("extern", 0) == 0 ? Scope::kNamespace : Scope::kType;
      else if (head.find(')') != std::string::npos && !assigns_outside_parentheses(head)) scope = Scope::kFunction;
      scopes.push_back(scope);
      starts.push_back(head_start);
      head_start = i + 1;
    } else if (c == '}') {
      if (scopes.empty()) continue;
      if (scopes.back() == Scope::kFunction) {
        const int first = line_at(starts.back());
        std::string head = code.substr(starts.back(), std::min<std::size_t>(120, code.find('{', starts.back()) - starts.back()));
        std::replace(head.begin(), head.end(), '\n', ' ');
        found.push_back({fs::relative(file, kSource).generic_string() + ":" + std::to_string(first), head, line_at(i) - first + 1});
      }
      scopes.pop_back();
      starts.pop_back();
      if (scopes.empty() || scopes.back() != Scope::kFunction) head_start = i + 1;
    }
  }
  return found;
}

// A function longer than a screen is a sign to split it (docs/architecture.md, "How the code is kept").
constexpr int kMaxFunctionLines = 80;

TEST(FunctionSize, TheScannerFindsFunctionsAndTheirLength) {
  const fs::path file = fs::path(PHYSLTL_TEST_OUTPUT_DIR) / "scanned.cpp";
  fs::create_directories(file.parent_path());
  std::ofstream(file) << "namespace a {\n"
                         "struct S { int f() const { return 1; } };\n"
                         "// not() { a function }\n"
                         "int g(int x) {\n"
                         "  auto h = [&](int y) { return \"}\" + y; };\n"
                         "  if (x) { return h(x); }\n"
                         "  return 0;\n"
                         "}\n"
                         "const int kTable[] = {1, 2};\n"
                         "}  // namespace a\n";
  const std::vector<FunctionLength> found = functions_of(file);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].lines, 1);
  EXPECT_EQ(found[1].lines, 5);
  EXPECT_NE(found[1].head.find("int g(int x)"), std::string::npos) << found[1].head;
}

TEST(FunctionSize, NoFunctionInTheProgramRunsOverEightyLines) {
  std::string longest;
  for (const fs::path& file : sources_under({"src"})) {
    for (const FunctionLength& f : functions_of(file)) {
      if (f.lines > kMaxFunctionLines) longest += f.where + ": " + std::to_string(f.lines) + " lines: " + f.head + "\n";
    }
  }
  EXPECT_TRUE(longest.empty()) << longest;
}

// The physltl namespaces a file's code opens at namespace scope, each in full ("physltl::ltl::detail"):
// anonymous namespaces add nothing to the name, other libraries' namespaces (a forward declaration of
// OMPL's classes) are left out.
std::set<std::string> namespaces_opened(const fs::path& file) {
  const std::string code = code_only(read(file));
  static const std::regex opening(R"(^\s*(?:inline\s+)?namespace\s*([A-Za-z_][\w:]*)?\s*$)");
  std::vector<std::string> scopes;  // each open brace: its namespace in full, or "{" for any other brace
  std::set<std::string> found;
  std::size_t head_start = 0;
  for (std::size_t i = 0; i < code.size(); ++i) {
    const char c = code[i];
    if (c == ';' || c == '}') head_start = i + 1;
    if (c == '}' && !scopes.empty()) scopes.pop_back();
    if (c != '{') continue;
    std::smatch m;
    static const std::regex directive(R"((^|\n)\s*#[^\n]*)");  // #include and #pragma lines before the first namespace
    const std::string head = std::regex_replace(code.substr(head_start, i - head_start), directive, "");
    const bool in_namespace_scope = scopes.empty() || scopes.back() != "{";
    if (in_namespace_scope && std::regex_match(head, m, opening)) {
      const std::string outer = scopes.empty() ? "" : scopes.back();
      const std::string name = !m[1].matched ? outer : outer.empty() ? m[1].str() : outer + "::" + m[1].str();
      scopes.push_back(name);
      if (name.rfind("physltl", 0) == 0) found.insert(name);
    } else {
      scopes.push_back("{");
    }
    head_start = i + 1;
  }
  return found;
}

// The files of src/ and include/physltl/ that open a namespace other than their module folder's (or one
// nested in it that is not another module's).
std::vector<std::string> namespaces_not_of_their_folder(const fs::path& root, const Modules& tree) {
  std::vector<std::string> wrong;
  for (const fs::path& file : sources_under(root, {"src", "include"})) {
    const std::string path = fs::relative(file, root).generic_string();
    const std::string module = tree.of(path);
    const std::string own = Modules::namespace_of(module);
    for (const std::string& name : namespaces_opened(file)) {
      bool fits = name == own || name.rfind(own + "::", 0) == 0;
      for (const std::string& other : tree.names()) {
        const std::string theirs = Modules::namespace_of(other);
        if (other != module && theirs.size() > own.size() && (name == theirs || name.rfind(theirs + "::", 0) == 0)) fits = false;
      }
      if (!fits) wrong.push_back(path + ": namespace " + name + " in module " + module + " (" + own + ")");
    }
  }
  return wrong;
}

TEST(Namespaces, EveryFileIsInItsModuleFoldersNamespace) {
  const std::vector<std::string> wrong = namespaces_not_of_their_folder(kSource, modules());
  EXPECT_TRUE(wrong.empty()) << lines_of(wrong);
  EXPECT_EQ(namespaces_opened(kSource / "src/planners/knowledge/tree_search.h"),
            std::set<std::string>{"physltl::planners::knowledge"});
}

// The checks above on a small tree of their own: a planner folder no table names (planners/b) that includes
// another planner, and a file of it in the core's namespace, are each found; the planner that keeps to
// itself (planners/a) is not.
TEST(Layers, ANewPlannerFolderThatIncludesAnotherOrLeavesItsNamespaceFails) {
  const fs::path root = fs::path(PHYSLTL_TEST_OUTPUT_DIR) / "module_tree";
  fs::remove_all(root);
  const auto write = [&](const std::string& path, const std::string& text) {
    fs::create_directories((root / path).parent_path());
    std::ofstream(root / path) << text;
  };
  for (const std::string module : {"planning", "planners", "planners/a", "planners/b"}) write("src/" + module + "/CMakeLists.txt", "");
  write("include/physltl/planners/a/entries.h", "#include \"physltl/planning/registry.h\"\nnamespace physltl::planners::a {}\n");
  write("src/planners/a/search.cpp", "#include \"physltl/planners/a/entries.h\"\nnamespace physltl::planners::a {\nnamespace {}\n}\n");
  write("src/planners/b/search.cpp", "#include \"physltl/planning/registry.h\"\n#include \"physltl/planners/a/entries.h\"\n"
                                     "namespace physltl::planning {\n}\n");
  const Modules tree(root);
  EXPECT_EQ(tree.planners(), (std::set<std::string>{"planners/a", "planners/b"}));
  EXPECT_EQ(tree.of("src/planners/b/search.cpp"), "planners/b");
  EXPECT_EQ(tree.of("physltl/planners/a/entries.h"), "planners/a");
  EXPECT_EQ(includes_between_planners(root, tree),
            std::vector<std::string>{"src/planners/b/search.cpp:2: planners/b includes planners/a"});
  EXPECT_EQ(namespaces_not_of_their_folder(root, tree),
            std::vector<std::string>{"src/planners/b/search.cpp: namespace physltl::planning in module planners/b (physltl::planners::b)"});
}

TEST(Namespaces, TheScannerNamesNestedNamespacesInFullAndSkipsOtherLibraries) {
  const fs::path file = fs::path(PHYSLTL_TEST_OUTPUT_DIR) / "namespaces.h";
  fs::create_directories(file.parent_path());
  std::ofstream(file) << "#include \"physltl/ltl/formula.h\"\n"
                         "namespace ompl::control { class World; }\n"
                         "namespace physltl::ltl {\n"
                         "namespace {\n"
                         "struct S { void f() { } };\n"
                         "}  // namespace\n"
                         "namespace detail { int g(); }\n"
                         "// namespace physltl::app { in a comment }\n"
                         "}\n";
  EXPECT_EQ(namespaces_opened(file), (std::set<std::string>{"physltl::ltl", "physltl::ltl::detail"}));
}

}  // namespace

namespace {

// The data members of `struct NAME { ... }` in `header`, by name, in order (member functions and nested
// types left out).
std::vector<std::string> members_of(const std::string& header, const std::string& name) {
  const std::string code = code_only(read(kSource / header));
  const std::size_t at = code.find("struct " + name + " {");
  if (at == std::string::npos) return {};
  std::vector<std::string> members;
  int depth = 0;
  std::string statement;
  for (std::size_t i = code.find('{', at); i < code.size(); ++i) {
    const char c = code[i];
    if (c == '{') ++depth;
    if (c == '}' && --depth == 0) break;
    if (depth == 1 && c == ';') {
      // A declaration at the struct's own level: a data member unless it declares a function.
      static const std::regex member(R"re(([A-Za-z_][A-Za-z_0-9]*)\s*(=[^;]*|\{[^;]*\})?\s*$)re");
      const std::string head = statement.substr(0, statement.find('='));
      std::smatch found;
      if (head.find('(') == std::string::npos && std::regex_search(statement, found, member)) members.push_back(found[1]);
      statement.clear();
    } else if (depth == 1 && c != '{') {
      statement += c;
    } else if (depth == 1) {
      statement += ' ';
    }
  }
  return members;
}

}  // namespace

// The planner contract is narrow on purpose (docs/architecture.md, "The planner contract"): one
// termination condition, the deadline, and fields every planner fills (improving a validated plan is the
// core's, ImprovementSettings, never a planner's option). A planner's own settings are
// parameters (PlannerEntry::parameters), its own data a PlannerData, its own counters
// PlannerStats::own_counts. A field added here is a change of the contract: add it to this list on purpose.
TEST(PlannerContract, TheSharedOptionsAndResultHoldOnlyTheContractsMembers) {
  const std::string header = "include/physltl/planning/planner_options.h";
  EXPECT_EQ(members_of(header, "PlannerOptions"),
            (std::vector<std::string>{"seed", "deadline", "max_propagations", "threads", "parameters"}));
  EXPECT_EQ(members_of(header, "PlannerStats"),
            (std::vector<std::string>{"planning_time_s", "propagations", "physics_steps", "tree_nodes", "invalid_steps",
                                      "refused", "own_counts"}));
  EXPECT_EQ(members_of(header, "PlanResult"),
            (std::vector<std::string>{"solved", "stop_reason", "plan", "tree", "stats", "own", "settings",
                                      "improved_itself", "motion_progress"}));
}

TEST(PlannerContract, TheMemberScannerReadsDefaultsAndSkipsFunctions) {
  // Guards the test above against a scanner that finds nothing: the Deadline class has no `struct`, so
  // PlannerOptions' own default-initialised members and its one member function must be told apart.
  const std::vector<std::string> options = members_of("include/physltl/planning/planner_options.h", "PlannerOptions");
  EXPECT_NE(std::find(options.begin(), options.end(), "seed"), options.end());
  EXPECT_EQ(std::find(options.begin(), options.end(), "parameter"), options.end());
  EXPECT_TRUE(members_of("include/physltl/planning/planner_options.h", "NoSuchStruct").empty());
}
