// The files of a load path's checkpoint (doc/theory.md §11, "Restart"):
// after every <Output/Checkpoint interval>-th later step the folder
// checkpoint/ in the output folder holds the mesh with the fields on its
// cells (p4est's save, written by ContactProblem::write_checkpoint()), the
// record of the path's state (state.txt, written and read here) and the
// parameters of the run (parameters.prm). `dualcontact scene.prm --resume
// folder/` goes on from it (ContactProblem::load_checkpoint()).
#ifndef dualcontact_checkpoint_h
#define dualcontact_checkpoint_h

#include <dualcontact/input_error.h>

#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace dualcontact
{
  /** The checkpoint folder of the output folder `directory`. */
  std::string
  checkpoint_folder(const std::string &directory);

  /**
   * The error of a checkpoint whose file `file` is missing, cut short or
   * altered (`what` says how), exit_cannot_read_file like any other
   * damaged input file.
   */
  InputError
  damaged_checkpoint(const std::string &file, const std::string &what);

  /**
   * The CRC-32 of the file `file` (zlib's checksum, as `crc32` prints it):
   * 8 hex digits; empty if the file cannot be read.
   */
  std::string
  file_checksum(const std::string &file);

  /**
   * `word` as a finite number, written whole (no space or other character
   * before or after it); false if it is not one.
   */
  bool
  read_number(const std::string &word, double &x);

  /** `word` as a whole number of digits alone; false if it is not one. */
  bool
  read_whole_number(const std::string &word, unsigned long long &n);

  /**
   * The scalars of a checkpoint: one "key value" per line, the numbers in
   * 17 significant digits, so that they read back exactly.
   *
   * A record read from a file trusts nothing in it: each value is checked
   * as it is taken, and a key that is missing, a number that does not parse
   * whole, is not finite or lies outside its range, a line that is not
   * "key value", a key given twice, a last line without its end (a copy cut
   * short) or a key that no reader takes (check_all_taken()) is
   * damaged_checkpoint() naming the file and the key. A resumed run then
   * stops with that message (exit 3) before it uses a value, instead of
   * failing inside deal.II or going on from numbers that do not hold
   * together.
   */
  class CheckpointRecord
  {
  public:
    void
    set(const std::string &key, const std::string &value);
    void
    set(const std::string &key, const double value);

    /** The value of `key`. */
    const std::string &
    text(const std::string &key) const;

    /** The value of `key`: a finite number, at least `lowest`. */
    double
    number(const std::string &key,
           const double lowest = -std::numeric_limits<double>::max()) const;

    /** The value of `key`: a whole number from `lowest` to `highest`. */
    unsigned long long
    whole_number(const std::string       &key,
                 const unsigned long long lowest,
                 const unsigned long long highest) const;

    /** The value of `key`: `n` whole numbers, separated by spaces. */
    std::vector<unsigned long long>
    whole_numbers(const std::string &key, const std::size_t n) const;

    /** The value of `key` split at its spaces. */
    std::vector<std::string>
    words(const std::string &key) const;

    /** Every key that begins with `prefix`, with its value. */
    std::map<std::string, std::string>
    with_prefix(const std::string &prefix) const;

    /** The error of a damaged record: `key`'s value `what` ("is not ..."). */
    InputError
    damaged(const std::string &key, const std::string &what) const;

    /** Throw damaged() for a key that no call above has taken. */
    void
    check_all_taken() const;

    void
    write(const std::string &filename) const;

    /**
     * Read `filename`; false if there is none. Throws damaged_checkpoint()
     * if its lines are not a record.
     */
    bool
    read(const std::string &filename);

  private:
    // the file read(), which the errors name
    std::string                        name_of_file;
    std::map<std::string, std::string> values;
    // the keys a reader has asked for
    mutable std::set<std::string> taken;
  };

  /**
   * The first entry (in the order of `now`) whose value differs between two
   * parameter listings in ParameterHandler's PRM format, or that only one
   * of them has, as "<Subsection/Entry> is 'a' in the scene and 'b' in the
   * checkpoint"; empty if they agree. The entries in `ignored`
   * ("Subsection/Entry") do not count; those in `first` are compared
   * before the others, in their order.
   */
  std::string
  first_difference(const std::string              &now,
                   const std::string              &saved,
                   const std::set<std::string>    &ignored,
                   const std::vector<std::string> &first = {});
} // namespace dualcontact

#endif
