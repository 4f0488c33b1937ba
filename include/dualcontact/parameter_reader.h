// Reading parameter files (.prm) into a ParameterHandler, with the project's
// rules and messages on top of deal.II's syntax (set, subsection, end,
// include, '#' comments, '\' continuation lines).
#ifndef dualcontact_parameter_reader_h
#define dualcontact_parameter_reader_h

#include <deal.II/base/parameter_handler.h>

#include <dualcontact/entry_declaration.h>

#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace dualcontact
{
  /**
   * Fills a ParameterHandler (whose entries are declared) from a scene file,
   * then from overrides. Unlike ParameterHandler::parse_input:
   * - every error is one line that names the entry as <Subsection/Entry>,
   *   the value given, what the entry expects in words (those its
   *   declaration recorded in the EntryCatalog, not deal.II's pattern text)
   *   and where the line is (file:line), and throws InputError with the
   *   project's exit code;
   * - an unknown entry or subsection gets the closest declared name as a
   *   suggestion ("did you mean <Friction/Coefficient>?");
   * - an entry set twice by the scene (its file and the files it includes)
   *   is an error naming both lines: one of the two values would be
   *   ignored without a word;
   * - 'include' paths are relative to the folder of the including file, so
   *   a scene and its overlays work from any working directory;
   * - overrides (the command line's --set, or an overlay text) are applied
   *   after the scene and may change any entry the scene set, once each.
   * The reader remembers which entries were given and where, for messages
   * and for the warnings on entries that have no effect.
   */
  class ParameterReader
  {
  public:
    /**
     * Reads into `prm`, whose entries were declared through an EntryDeclarer
     * whose catalog() is `catalog`: the reader knows the subsections, the
     * entries, their defaults and their patterns in words from it.
     */
    ParameterReader(dealii::ParameterHandler &prm, EntryCatalog catalog);
    ~ParameterReader();

    /** The scene file. InputError (exit 3) if it cannot be read. */
    void
    read_file(const std::string &filename);

    /** The scene as .prm text; `source` names it in messages. */
    void
    read_text(const std::string &text, const std::string &source);

    /** .prm text applied after the scene: it may change the scene's values. */
    void
    read_overlay(const std::string &text, const std::string &source);

    /**
     * One override "Subsection/Entry=value" (nested subsections with more
     * '/'), as the command line's --set gives it. A malformed one (no '=',
     * no '/') is a usage error (exit 2).
     */
    void
    set_override(const std::string &assignment);

    /**
     * The entries given a value other than their default, as
     * "Subsection/Entry", each with where its value comes from
     * ("scene.prm:12", or "--set").
     */
    std::map<std::string, std::string>
    given_entries() const;

    /**
     * Every entry the scene or an override set, whatever its value (also
     * one set to its default), as "Subsection/Entry".
     */
    std::set<std::string>
    set_entries() const;

    /**
     * The folder of the file that set `entry` ("Subsection/Entry"), for
     * paths relative to it: empty (the working directory) for an override,
     * a text, or an entry not given.
     */
    std::filesystem::path
    folder_of(const std::string &entry) const;

    /** Whether the scene (not counting overrides) set at least one entry. */
    bool
    scene_has_entries() const;

  private:
    struct Layer;

    void
    read_stream(std::istream                &in,
                const std::string           &source,
                const std::filesystem::path &folder,
                Layer                       &layer);
    void
    read_included_file(const std::filesystem::path &file,
                       const std::string           &where,
                       Layer                       &layer);
    void
    scan_line(const std::string           &line,
              const std::string           &where,
              const std::filesystem::path &folder,
              std::size_t                  depth_at_file_start,
              Layer                       &layer);
    void
    enter(const std::string &subsection, const std::string &where);
    void
    assign(const std::vector<std::string> &subsections,
           const std::string              &entry,
           const std::string              &value,
           const std::string              &where,
           const std::filesystem::path    &folder,
           Layer                          &layer);

    dealii::ParameterHandler &prm;
    EntryCatalog              catalog;
    std::unique_ptr<Layer>    scene;
    std::unique_ptr<Layer>    overrides;
    // the subsections the file being read is in, with where each was opened
    std::vector<std::pair<std::string, std::string>> path;
    // the files being read, to catch a file that includes itself
    std::vector<std::filesystem::path> open_files;
  };

  /**
   * The candidate closest to `word` (case-insensitive edit distance, a
   * transposition counting as one edit), or "" if none is close enough to
   * be a likely misspelling.
   */
  std::string
  closest_match(const std::string              &word,
                const std::vector<std::string> &candidates);
} // namespace dualcontact

#endif
